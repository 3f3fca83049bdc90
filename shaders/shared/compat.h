// Lets a header be included by both GLSL and C++ (with GLM), so structs and small functions shared
// by shaders and CPU code are written once. In shared code: float literals carry an f suffix (GLM
// templates do not mix float and double), functions are declared CANDELA_FN, and everything sits
// between CANDELA_NAMESPACE_BEGIN/END.
#ifndef CANDELA_SHARED_COMPAT_H
#define CANDELA_SHARED_COMPAT_H

#ifdef __cplusplus
#include <glm/glm.hpp>
#include <cstdint>
#define CANDELA_NAMESPACE_BEGIN \
    namespace candela::shading { \
    using namespace glm;        \
    using uint = uint32_t;
#define CANDELA_NAMESPACE_END }
#define CANDELA_FN inline
#else
#define CANDELA_NAMESPACE_BEGIN
#define CANDELA_NAMESPACE_END
#define CANDELA_FN
#endif

#endif
