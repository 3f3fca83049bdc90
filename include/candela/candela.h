#pragma once
// Candela's public C++ API: #include <candela/candela.h> and link Candela::candela (docs/embedding.md).

#include "candela/dataset.h"
#include "candela/device.h"
#include "candela/errors.h"
#include "candela/image.h"
#include "candela/render.h"
#include "candela/scene.h"
#include "candela/version.h"
