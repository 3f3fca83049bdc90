// UI annotations in GLSL comments (shader/annotations.h), parsed from text.
#include "shader/annotations.h"

#include <gtest/gtest.h>

namespace candela::shader {
namespace {

TEST(Annotations, ColorIgnoreAndRangeOnStructAndBlockMembers) {
    const auto a = parseAnnotations(R"(
        #version 460
        struct Params {
            /*Color*/ vec4 tint;
            /*Range(-8, 8.5)*/ float exposure;
            /*Ignore*/ float pad0, pad1;
            float plain;  // not annotated
        };
        layout(push_constant) uniform Push {
            /*Range(0, 1)*/ /*Color*/ vec3 both;
            Params params;
        } push;
        layout(std430, set = 0, binding = 0) readonly buffer Lights {
            /*Ignore*/ uint count;
        };
    )");
    ASSERT_EQ(a.size(), 6u);
    EXPECT_TRUE(a.at("Params.tint").color);
    EXPECT_EQ(a.at("Params.exposure").min, -8.0f);
    EXPECT_EQ(a.at("Params.exposure").max, 8.5f);
    EXPECT_TRUE(a.at("Params.pad0").ignore);
    EXPECT_TRUE(a.at("Params.pad1").ignore);
    EXPECT_FALSE(a.count("Params.plain"));
    EXPECT_TRUE(a.at("Push.both").color);
    EXPECT_EQ(a.at("Push.both").max, 1.0f);
    EXPECT_TRUE(a.at("Lights.count").ignore);
}

TEST(Annotations, ArraysAndMultiLineDeclarations) {
    const auto a = parseAnnotations("struct S {\n  /*Ignore*/\n  vec4 uv[CANDELA_TEX_COUNT];\n  /*Color*/ vec3\n  albedo;\n};");
    EXPECT_TRUE(a.at("S.uv").ignore);
    EXPECT_TRUE(a.at("S.albedo").color);
}

TEST(Annotations, OnlyDirectlyBeforeADeclaration) {
    // After the type, inside a function, at global scope or in a line comment: not annotations.
    const auto a = parseAnnotations(R"(
        /*Color*/ uniform vec3 loose;
        struct S { vec3 /*Color*/ late; float x; /*Color*/ };
        void main() { /*Ignore*/ float local; }
        struct T { // /*Color*/
            vec3 commented; };
    )");
    EXPECT_TRUE(a.empty());
}

TEST(Annotations, MalformedAnnotationsAreIgnored) {
    const auto a = parseAnnotations(R"(struct S {
        /*Range(1)*/ float a;
        /*Range(2, 1)*/ float b;
        /*Range(x, 1)*/ float c;
        /*color*/ vec3 d;
        /*Range(0, 1) trailing*/ float e;
        /*Range(0,1)*/ float good;
    };)");
    ASSERT_EQ(a.size(), 1u);
    EXPECT_EQ(a.at("S.good").max, 1.0f);
}

TEST(Annotations, PreprocessorLinesAndUnterminatedTextAreSafe) {
    EXPECT_TRUE(parseAnnotations("#define X struct S { /*Color*/ vec3 c; }\n").empty());
    EXPECT_TRUE(parseAnnotations("struct S { /*Color").empty());
    EXPECT_TRUE(parseAnnotations("}}}} struct {").empty());
    EXPECT_TRUE(parseAnnotations("").empty());
}

}  // namespace
}  // namespace candela::shader
