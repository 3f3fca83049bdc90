// The Python module `candela._candela` (re-exported by candela/__init__.py; docs/python.md): a
// binding of the public C++ API (include/candela/) with pybind11. Images are NumPy arrays that the
// read-back writes into directly; the GIL is released while Candela loads and renders; the API's
// exceptions become candela.Error and its subclasses, carrying the message the command line prints.

#include "candela/candela.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;

namespace {

// --- Exceptions -----------------------------------------------------------------------------

// The Python exception types, made once at import (module-lifetime references).
struct ErrorTypes {
    py::object error, input, device, deviceLost, outOfMemory, cancelled, internal;
};
ErrorTypes& errorTypes() {
    static ErrorTypes* types = new ErrorTypes();  // leaked: outlives the interpreter's teardown order
    return *types;
}

void registerErrors(py::module_& m) {
    ErrorTypes& t = errorTypes();
    const auto make = [&](const char* name, py::handle base, const char* doc) {
        py::object type = py::reinterpret_steal<py::object>(
            PyErr_NewExceptionWithDoc((std::string("candela.") + name).c_str(), doc, base.ptr(), nullptr));
        if (!type) throw py::error_already_set();
        m.attr(name) = type;
        return type;
    };
    t.error = make("Error", PyExc_RuntimeError, "Base of every error Candela raises; str() is one line.");
    t.input = make("InputError", t.error,
                   "Bad input: a malformed or missing file, a setting out of range. `file` names the file "
                   "('' for a setting), `reason` says what is wrong; str() is 'FILE: REASON'.");
    t.device = make("DeviceError", t.error, "The device failed: no Vulkan 1.3 device, or a Vulkan call failed.");
    t.deviceLost = make("DeviceLostError", t.device, "The device was lost: close the Device; a new one may work.");
    t.outOfMemory = make("OutOfMemoryError", t.device,
                         "Device memory ran out (or the memory budget was reached); the Device stays usable.");
    t.cancelled = make("CancelledError", t.error, "The render was cancelled (Device.cancel()).");
    t.internal = make("InternalFailure", t.error, "A bug in Candela: please report it with the message and the input.");

    py::register_exception_translator([](std::exception_ptr thrown) {
        ErrorTypes& types = errorTypes();
        const auto raise = [](const py::object& type, const std::exception& e) { PyErr_SetString(type.ptr(), e.what()); };
        try {
            std::rethrow_exception(thrown);
        } catch (const candela::InputError& e) {
            py::object instance = types.input(e.what());
            instance.attr("file") = e.file();
            instance.attr("reason") = e.reason();
            PyErr_SetObject(types.input.ptr(), instance.ptr());
        } catch (const candela::DeviceLostError& e) {
            raise(types.deviceLost, e);
        } catch (const candela::OutOfMemoryError& e) {
            raise(types.outOfMemory, e);
        } catch (const candela::DeviceError& e) {
            raise(types.device, e);
        } catch (const candela::CancelledError& e) {
            raise(types.cancelled, e);
        } catch (const candela::InternalFailure& e) {
            raise(types.internal, e);
        } catch (const candela::Error& e) {
            raise(types.error, e);
        }
    });
}

[[noreturn]] void inputError(const std::string& reason) { throw candela::InputError("", reason); }

// --- Conversions ------------------------------------------------------------------------------

std::array<float, 3> vec3Of(const py::handle& value, const char* what) {
    const auto v = py::cast<std::vector<float>>(value);
    if (v.size() != 3) inputError(std::string(what) + ": 3 numbers, not " + std::to_string(v.size()));
    return {v[0], v[1], v[2]};
}

// A column-major array of a 4×4 matrix given as a NumPy array or nested sequence (row-major).
std::array<float, 16> matrixOf(const py::handle& value, const char* what) {
    const auto rows = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(value);
    if (!rows || rows.ndim() != 2 || rows.shape(0) != 4 || rows.shape(1) != 4) inputError(std::string(what) + ": a 4x4 matrix");
    std::array<float, 16> out{};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) out[size_t(4 * c + r)] = rows.at(r, c);
    return out;
}

// A row-major NumPy copy of the column-major `m` (rows × cols).
py::array_t<double> arrayOf(const float* m, int rows, int cols) {
    py::array_t<double> out({rows, cols});
    auto view = out.mutable_unchecked<2>();
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) view(r, c) = m[c * rows + r];
    return out;
}

// --- Camera --------------------------------------------------------------------------------------

// Intrinsics from a 3×3 K (fx, fy, cx, cy; no skew) or from fov_y; the other field of `camera`.
void setIntrinsics(candela::Camera& camera, const py::object& fovY, const py::object& K) {
    if (!K.is_none()) {
        if (!fovY.is_none()) inputError("Camera: give fov_y or K, not both");
        const auto k = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(K);
        if (!k || k.ndim() != 2 || k.shape(0) != 3 || k.shape(1) != 3) inputError("Camera: K is a 3x3 matrix");
        if (k.at(0, 1) != 0.0 || k.at(1, 0) != 0.0 || k.at(2, 0) != 0.0 || k.at(2, 1) != 0.0 || k.at(2, 2) != 1.0)
            inputError("Camera: K must be [[fx, 0, cx], [0, fy, cy], [0, 0, 1]] (no skew)");
        camera.intrinsics = std::array<float, 4>{float(k.at(0, 0)), float(k.at(1, 1)), float(k.at(0, 2)), float(k.at(1, 2))};
    } else if (!fovY.is_none()) {
        camera.fovYDegrees = py::cast<float>(fovY);
    }
}

std::string describe(const candela::Camera& camera) {
    std::string out = "Camera(";
    if (camera.gltfCamera) return out + "gltf=" + std::to_string(*camera.gltfCamera) + ")";
    if (camera.cameraToWorld) out += "placed";
    else if (camera.orbit)
        out += "orbit " + std::to_string((*camera.orbit)[0]) + "," + std::to_string((*camera.orbit)[1]) + "," +
               std::to_string((*camera.orbit)[2]);
    else out += "framed";
    if (camera.intrinsics) out += ", K";
    else if (camera.fovYDegrees) out += ", fov_y=" + std::to_string(*camera.fovYDegrees);
    return out + ")";
}

// --- Device -------------------------------------------------------------------------------------

// candela.Device: a candela::Device that close() (or leaving a `with` block) destroys. `busy` is
// held, without the GIL, by whatever uses the device, so that a close() or render() from another
// Python thread waits for the one in progress (candela::Device is used from one thread at a time).
struct PyDevice {
    std::optional<candela::Device> device;
    std::mutex busy;
    // Precondition: `busy` is held.
    candela::Device& get() {
        if (!device) throw candela::Error("the Device is closed");
        return *device;
    }
    // Runs `use` on the device with `busy` held and the GIL released.
    template <typename Use>
    auto with(Use use) {
        py::gil_scoped_release released;
        std::lock_guard lock(busy);
        return use(get());
    }
    void close() {
        py::gil_scoped_release released;
        std::lock_guard lock(busy);
        device.reset();
    }
};

// The settings render() and render_sequence() accept besides the scene: parsed from keywords
// (unknown ones are a TypeError naming them).
struct RenderCall {
    candela::RenderOptions options;
    const candela::Environment* environment = nullptr;
    py::object environmentRef;  // keeps `environment` alive
    std::vector<std::string> outputs{"color"};
    py::dtype dtype = py::dtype::of<uint8_t>();
};

candela::Tonemap tonemapOf(const std::string& name) {
    if (name == "pbr-neutral") return candela::Tonemap::PbrNeutral;
    if (name == "aces") return candela::Tonemap::Aces;
    if (name == "agx") return candela::Tonemap::Agx;
    if (name == "reinhard") return candela::Tonemap::Reinhard;
    if (name == "linear") return candela::Tonemap::Linear;
    inputError("tonemap '" + name + "': choose from pbr-neutral, aces, agx, reinhard, linear");
}

candela::ShadingPath shadingPathOf(const std::string& name) {
    if (name == "auto") return candela::ShadingPath::Auto;
    if (name == "forward") return candela::ShadingPath::Forward;
    if (name == "visibility") return candela::ShadingPath::Visibility;
    inputError("shading_path '" + name + "': choose from auto, forward, visibility");
}

candela::Background backgroundOf(const py::handle& value) {
    using Kind = candela::Background::Kind;
    if (py::isinstance<py::str>(value)) {
        const auto name = py::cast<std::string>(value);
        if (name == "auto") return {Kind::Auto, {}};
        if (name == "environment") return {Kind::Environment, {}};
        if (name == "transparent") return {Kind::Transparent, {}};
        inputError("background '" + name + "': choose from auto, environment, transparent, or (r, g, b) in sRGB");
    }
    return {Kind::Color, vec3Of(value, "background")};
}

RenderCall renderCall(const py::kwargs& kwargs, bool sequence, candela::SequenceOptions* sequenceOptions) {
    RenderCall call;
    candela::RenderOptions& o = call.options;
    for (const auto& [key, value] : kwargs) {
        const auto name = py::cast<std::string>(key);
        if (name == "width") o.width = py::cast<uint32_t>(value);
        else if (name == "height") o.height = py::cast<uint32_t>(value);
        else if (name == "camera") {
            if (!value.is_none()) o.camera = py::cast<candela::Camera>(value);
        } else if (name == "environment") {
            if (!value.is_none()) {
                call.environment = py::cast<const candela::Environment*>(value);
                call.environmentRef = py::reinterpret_borrow<py::object>(value);
            }
        } else if (name == "outputs") {
            call.outputs = py::isinstance<py::str>(value) ? std::vector<std::string>{py::cast<std::string>(value)}
                                                          : py::cast<std::vector<std::string>>(value);
        } else if (name == "dtype") call.dtype = py::dtype::from_args(py::reinterpret_borrow<py::object>(value));
        else if (name == "tonemap") o.tonemap = tonemapOf(py::cast<std::string>(value));
        else if (name == "exposure") o.exposureEv = py::cast<float>(value);
        else if (name == "msaa") {
            if (!value.is_none()) o.msaa = py::cast<uint32_t>(value);
        } else if (name == "shading_path") o.shadingPath = shadingPathOf(py::cast<std::string>(value));
        else if (name == "background") o.background = backgroundOf(value);
        else if (name == "dither") o.dither = py::cast<bool>(value);
        else if (name == "animations") {
            o.animations = py::isinstance<py::str>(value) ? std::vector<std::string>{py::cast<std::string>(value)}
                                                          : py::cast<std::vector<std::string>>(value);
        } else if (name == "time") o.time = py::cast<double>(value);
        else if (name == "variant") o.variant = value.is_none() ? "" : py::cast<std::string>(value);
        else if (name == "environment_rotation") o.environmentRotationDegrees = py::cast<float>(value);
        else if (sequence && name == "frames") sequenceOptions->frames = py::cast<uint32_t>(value);
        else if (sequence && name == "fps") sequenceOptions->fps = py::cast<double>(value);
        else if (sequence && name == "turntable") sequenceOptions->turntableDegrees = py::cast<float>(value);
        else if (sequence && name == "views") sequenceOptions->views = py::cast<std::vector<std::array<float, 2>>>(value);
        else if (sequence && name == "lighting_seed") {
            if (!value.is_none()) sequenceOptions->lightingSeed = py::cast<uint64_t>(value);
        }
        else throw py::type_error("unexpected keyword argument '" + name + "'");
    }
    if (call.outputs.empty()) inputError("outputs: ask for at least one");
    o.outputs.clear();
    for (const std::string& output : call.outputs) {
        const std::vector<candela::Output> named = candela::outputsNamed(output);
        if (named.empty()) {
            std::string known;
            for (candela::Output each : candela::allOutputs()) known += std::string(candela::outputName(each)) + ", ";
            inputError("outputs: '" + output + "' is not an output; choose from " + known + "ids");
        }
        for (candela::Output each : named)
            if (std::find(o.outputs.begin(), o.outputs.end(), each) == o.outputs.end()) o.outputs.push_back(each);
    }
    std::sort(o.outputs.begin(), o.outputs.end());
    if (call.dtype.equal(py::dtype::of<uint8_t>())) o.format = candela::PixelFormat::Rgba8Srgb;
    else if (call.dtype.equal(py::dtype::of<float>())) o.format = candela::PixelFormat::Rgba32Float;
    else if (call.dtype.equal(py::dtype("float16"))) o.format = candela::PixelFormat::Rgba16Float;
    else inputError("dtype " + py::cast<std::string>(py::str(call.dtype)) + ": uint8 (sRGB), float16 or float32 (linear)");
    return call;
}

// Renders one image of `scene` as `call` asks: a candela.Frame (a dict of NumPy arrays with a
// `camera`). The colour array is allocated first and read back into; the GIL is released meanwhile.
// An output besides colour as a NumPy array that owns its values (moved, not copied): H×W for one
// channel, else H×W×C; float32, or uint32 for the IDs.
template <typename T>
py::array ownedArray(std::vector<T>&& values, const candela::OutputImage& image) {
    auto* held = new std::vector<T>(std::move(values));
    py::capsule owner(held, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    std::vector<py::ssize_t> shape{py::ssize_t(image.height), py::ssize_t(image.width)};
    if (image.channels > 1) shape.push_back(py::ssize_t(image.channels));
    return py::array_t<T>(shape, held->data(), owner);
}

py::object renderOne(PyDevice& self, const candela::Scene& scene, const RenderCall& call) {
    const candela::RenderOptions& o = call.options;
    if (o.width == 0 || o.height == 0) inputError("an image of " + std::to_string(o.width) + "x" + std::to_string(o.height) + " pixels");
    py::object frame = py::module_::import("candela").attr("Frame")();
    frame.attr("environment_rotation") = o.environmentRotationDegrees;
    if (o.outputs != std::vector<candela::Output>{candela::Output::Color}) {
        // Outputs besides colour: the image in host memory, each output's values moved into its array.
        candela::Image image = self.with([&](candela::Device& device) { return device.render(scene, o, call.environment); });
        if (!image.pixels.empty()) {
            py::array color(call.dtype, std::vector<py::ssize_t>{py::ssize_t(o.height), py::ssize_t(o.width), 4});
            std::memcpy(color.mutable_data(), image.pixels.data(), image.pixels.size());
            frame["color"] = color;
        }
        for (candela::OutputImage& output : image.outputs)
            frame[candela::outputName(output.output)] =
                output.ids.empty() ? ownedArray(std::move(output.values), output) : ownedArray(std::move(output.ids), output);
        frame.attr("camera") = py::cast(image.camera);
        return frame;
    }
    py::array color(call.dtype, std::vector<py::ssize_t>{py::ssize_t(o.height), py::ssize_t(o.width), 4});
    void* pixels = color.mutable_data();
    const size_t rowBytes = size_t(o.width) * candela::bytesPerPixel(o.format);
    const candela::CameraInfo camera = self.with([&](candela::Device& device) {
        return device.renderInto(pixels, rowBytes, scene, o, call.environment);
    });
    frame["color"] = color;
    frame.attr("camera") = py::cast(camera);
    return frame;
}

// render_sequence's iterator: frame i of the sequence on each next() (candela::sequenceFrame).
struct SequenceIterator {
    py::object device;  // PyDevice
    py::object scene;   // candela::Scene
    RenderCall call;
    candela::SequenceOptions sequence;
    uint32_t next = 0;

    py::object advance() {
        if (next >= candela::frameCount(sequence)) throw py::stop_iteration();
        const auto& held = py::cast<const candela::Scene&>(scene);
        RenderCall frameCall = call;
        frameCall.options = candela::sequenceFrame(held, call.options, sequence, next);
        ++next;
        return renderOne(py::cast<PyDevice&>(device), held, frameCall);
    }
};

// Reads a path (str or os.PathLike) or the bytes of a file, without the GIL.
template <typename FromFile, typename FromMemory>
auto load(const py::object& source, const std::string& name, FromFile fromFile, FromMemory fromMemory) {
    if (py::isinstance<py::bytes>(source) || py::isinstance<py::bytearray>(source) || py::isinstance<py::memoryview>(source)) {
        const py::buffer_info buffer = py::buffer(source).request();
        const std::span<const std::byte> bytes(static_cast<const std::byte*>(buffer.ptr), size_t(buffer.size * buffer.itemsize));
        py::gil_scoped_release released;
        return fromMemory(bytes, name.empty() ? std::string("<bytes>") : name);
    }
    const std::string path = py::cast<std::filesystem::path>(source).string();
    py::gil_scoped_release released;
    return fromFile(path);
}

candela::Scene loadScene(const py::object& source, const std::string& name, std::optional<uint32_t> sceneIndex) {
    return load(source, name, [&](const std::string& path) { return candela::Scene::fromFile(path, sceneIndex); },
                [&](std::span<const std::byte> bytes, const std::string& label) {
                    return candela::Scene::fromMemory(bytes, label, {}, sceneIndex);
                });
}
constexpr const char* kLoadSceneDoc =
    "A .gltf/.glb from a path, or from bytes (`name` names it in messages; a URI to another file is an "
    "InputError); `scene` picks one of the file's scenes (None: its default).";

candela::Environment loadEnvironment(const py::object& source, const std::string& name) {
    if (source.is_none()) return candela::Environment::sky();
    return load(source, name, [](const std::string& path) { return candela::Environment::fromFile(path); },
                [](std::span<const std::byte> bytes, const std::string& label) {
                    return candela::Environment::fromMemory(bytes, label);
                });
}
constexpr const char* kLoadEnvironmentDoc = "A .hdr/.exr from a path or bytes; None: the built-in sky.";

}  // namespace

PYBIND11_MODULE(_candela, m) {
    m.doc() = "Candela's C++ API for Python (import candela; docs/python.md).";
    m.attr("__version__") = candela::version();
    m.attr("NO_ID") = candela::NoId;
    py::list outputNames;
    for (candela::Output output : candela::allOutputs()) outputNames.append(candela::outputName(output));
    m.attr("OUTPUTS") = py::tuple(outputNames);
    registerErrors(m);

    py::class_<candela::CameraInfo>(m, "CameraInfo",
                                    "The camera an image was rendered with: glTF's axes (the camera looks down -Z, +Y up),\n"
                                    "intrinsics in pixels with v down and pixel (i, j) centred at (i + 0.5, j + 0.5).")
        .def_readonly("width", &candela::CameraInfo::width)
        .def_readonly("height", &candela::CameraInfo::height)
        .def_property_readonly("camera_to_world", [](const candela::CameraInfo& c) { return arrayOf(c.cameraToWorld.data(), 4, 4); },
                               "4x4 camera-to-world matrix (row-major NumPy; metres)")
        .def_property_readonly("K", [](const candela::CameraInfo& c) {
            const float k[9] = {c.intrinsics[0], 0.0f, 0.0f, 0.0f, c.intrinsics[1], 0.0f, c.intrinsics[2], c.intrinsics[3], 1.0f};
            return arrayOf(k, 3, 3);
        }, "3x3 intrinsic matrix [[fx, 0, cx], [0, fy, cy], [0, 0, 1]] in pixels (zeros for an orthographic camera)")
        .def_property_readonly("projection", [](const candela::CameraInfo& c) { return arrayOf(c.projection.data(), 4, 4); },
                               "4x4 projection drawn with: Vulkan clip space (y down), reverse Z")
        .def_readonly("fov_y", &candela::CameraInfo::fovYDegrees, "vertical field of view in degrees (perspective)")
        .def_readonly("near", &candela::CameraInfo::znear)
        .def_readonly("far", &candela::CameraInfo::zfar, "far plane (inf: none)")
        .def_readonly("orthographic", &candela::CameraInfo::orthographic)
        .def_readonly("xmag", &candela::CameraInfo::xmag)
        .def_readonly("ymag", &candela::CameraInfo::ymag)
        .def("__repr__", [](const candela::CameraInfo& c) {
            return "CameraInfo(" + std::to_string(c.width) + "x" + std::to_string(c.height) + ", fov_y=" + std::to_string(c.fovYDegrees) + ")";
        });

    py::class_<candela::Camera>(m, "Camera",
                                "Where the camera is: framed (the default), an orbit, a look-at or a camera-to-world\n"
                                "matrix, or a glTF camera of the scene; with a vertical field of view or intrinsics K.")
        .def(py::init([](const py::object& fovY, const py::object& K) {
                 candela::Camera camera;
                 setIntrinsics(camera, fovY, K);
                 return camera;
             }),
             py::kw_only(), py::arg("fov_y") = py::none(), py::arg("K") = py::none(),
             "The orbit camera framing the scene's bounds from the scene's default direction.")
        .def_static("orbit",
                    [](float azimuth, float polar, float distance, const py::object& target, const py::object& fovY, const py::object& K) {
                        candela::Camera camera;
                        camera.orbit = std::array<float, 3>{azimuth, polar, distance};
                        if (!target.is_none()) camera.target = vec3Of(target, "target");
                        setIntrinsics(camera, fovY, K);
                        return camera;
                    },
                    py::arg("azimuth") = 0.0f, py::arg("polar") = 75.0f, py::arg("distance") = 0.0f, py::kw_only(),
                    py::arg("target") = py::none(), py::arg("fov_y") = py::none(), py::arg("K") = py::none(),
                    "Azimuth about +Y (0: on +Z) and polar angle from +Y in degrees; distance <= 0 frames the bounds.")
        .def_static("look_at",
                    [](const py::object& eye, const py::object& target, const py::object& up, const py::object& fovY, const py::object& K) {
                        candela::Camera camera = candela::lookAt(vec3Of(eye, "eye"), vec3Of(target, "target"), vec3Of(up, "up"));
                        setIntrinsics(camera, fovY, K);
                        return camera;
                    },
                    py::arg("eye"), py::arg("target"), py::arg("up") = std::vector<float>{0.0f, 1.0f, 0.0f}, py::kw_only(),
                    py::arg("fov_y") = py::none(), py::arg("K") = py::none(), "A camera at `eye` looking at `target`.")
        .def_static("from_matrix",
                    [](const py::object& cameraToWorld, const py::object& fovY, const py::object& K) {
                        candela::Camera camera;
                        camera.cameraToWorld = matrixOf(cameraToWorld, "camera_to_world");
                        setIntrinsics(camera, fovY, K);
                        return camera;
                    },
                    py::arg("camera_to_world"), py::kw_only(), py::arg("fov_y") = py::none(), py::arg("K") = py::none(),
                    "A camera placed by its 4x4 camera-to-world matrix (glTF's axes, as CameraInfo.camera_to_world).")
        .def_static("gltf", [](uint32_t index) {
            candela::Camera camera;
            camera.gltfCamera = index;
            return camera;
        }, py::arg("index"), "The scene's glTF camera of this index.")
        .def("__repr__", &describe);

    py::class_<candela::Scene>(m, "Scene", "A glTF 2.0 scene read on the host, drawn by any Device.")
        .def_static("sphere_grid", &candela::Scene::sphereGrid, py::arg("count") = 7, "The built-in grid of count x count spheres.")
        .def_property_readonly("name", &candela::Scene::name)
        .def_property_readonly("variants", &candela::Scene::variants)
        .def_property_readonly("animations", &candela::Scene::animations)
        .def_property_readonly("warnings", &candela::Scene::warnings)
        .def("__repr__", [](const candela::Scene& s) { return "Scene('" + s.name() + "')"; });

    py::class_<candela::Environment>(m, "Environment", "An equirectangular environment (.hdr, .exr) or the built-in sky.")
        .def_static("sky", &candela::Environment::sky)
        .def_property_readonly("name", &candela::Environment::name)
        .def_property_readonly("width", &candela::Environment::width)
        .def_property_readonly("height", &candela::Environment::height)
        .def_property_readonly("warnings", &candela::Environment::warnings)
        .def("__repr__", [](const candela::Environment& e) { return "Environment('" + e.name() + "')"; });

    m.def("load_scene", &loadScene, py::arg("source"), py::kw_only(), py::arg("name") = "", py::arg("scene") = py::none(),
          kLoadSceneDoc);
    m.def("load_environment", &loadEnvironment, py::arg("source") = py::none(), py::kw_only(), py::arg("name") = "",
          kLoadEnvironmentDoc);

    py::class_<SequenceIterator>(m, "SequenceIterator", "The frames of Device.render_sequence, rendered as they are asked for.")
        .def("__iter__", [](py::object self) { return self; })
        .def("__next__", &SequenceIterator::advance)
        .def("__len__", [](const SequenceIterator& s) { return candela::frameCount(s.sequence) - s.next; });

    const auto tuples = [](const std::vector<std::array<float, 2>>& views) {
        py::list out;
        for (const auto& view : views) out.append(py::make_tuple(view[0], view[1]));
        return out;
    };
    m.def("write_image",
          [](const std::filesystem::path& path, const py::array& pixels) {
              candela::Image image;
              if (pixels.ndim() != 3 || pixels.shape(2) != 4) inputError(path.string() + ": write_image takes an H x W x 4 array");
              image.height = uint32_t(pixels.shape(0));
              image.width = uint32_t(pixels.shape(1));
              if (pixels.dtype().equal(py::dtype::of<uint8_t>())) image.format = candela::PixelFormat::Rgba8Srgb;
              else if (pixels.dtype().equal(py::dtype::of<float>())) image.format = candela::PixelFormat::Rgba32Float;
              else if (pixels.dtype().equal(py::dtype("float16"))) image.format = candela::PixelFormat::Rgba16Float;
              else inputError(path.string() + ": write_image takes uint8, float16 or float32 pixels");
              const auto contiguous = py::array::ensure(pixels, py::array::c_style);
              image.pixels.resize(size_t(contiguous.nbytes()));
              std::memcpy(image.pixels.data(), contiguous.data(), image.pixels.size());
              py::gil_scoped_release released;
              candela::writeImage(path.string(), image);
          },
          py::arg("path"), py::arg("pixels"),
          "Writes an H x W x 4 array as `candela render --out` does: .png from uint8 (sRGB), .exr or .pfm from float16 "
          "or float32 (linear), through a temporary file renamed into place.");
    m.def("sphere_views", [tuples](uint32_t count) { return tuples(candela::sphereViews(count)); }, py::arg("count"),
          "count (azimuth, polar) directions in degrees spread evenly over the sphere (a Fibonacci lattice), for "
          "render_sequence(views=...)");
    m.def("ring_views", [tuples](uint32_t count, float elevation) { return tuples(candela::ringViews(count, elevation)); },
          py::arg("count"), py::arg("elevation"),
          "count (azimuth, polar) directions in degrees on a ring `elevation` degrees above the horizon");
    m.def("transforms_json",
          [](const py::iterable& frames) {
              std::vector<candela::DatasetFrame> out;
              for (const py::handle& item : frames) {
                  const auto pair = py::cast<py::tuple>(item);
                  if (pair.size() != 2) throw py::type_error("transforms_json: expected (file, Frame) pairs");
                  const py::object frame = pair[1];
                  out.push_back({.file = py::cast<std::filesystem::path>(pair[0]).generic_string(),
                                 .camera = py::cast<candela::CameraInfo>(frame.attr("camera")),
                                 .environmentRotationDegrees = py::cast<float>(frame.attr("environment_rotation"))});
              }
              return candela::transformsJson(out);
          },
          py::arg("frames"),
          "The cameras of (file, Frame) pairs as NeRF's transforms.json text (files relative to its folder), as "
          "`candela render --views` writes it.");

    py::class_<PyDevice>(m, "Device", "A Vulkan 1.3 device and a renderer on it; a context manager (close() on exit).")
        .def(py::init([](const std::string& device, const std::string& profile, bool validation, const std::string& pipelineCache,
                         const std::string& iblCache, const std::string& lodCache, uint32_t memoryBudgetMib) {
                 auto out = std::make_unique<PyDevice>();
                 const candela::DeviceOptions options{.device = device, .profile = profile, .validation = validation,
                                                      .pipelineCache = pipelineCache, .iblCache = iblCache,
                                                      .lodCache = lodCache, .memoryBudgetMib = memoryBudgetMib};
                 py::gil_scoped_release released;
                 out->device.emplace(options);
                 return out;
             }),
             py::kw_only(), py::arg("device") = "", py::arg("profile") = "", py::arg("validation") = false,
             py::arg("pipeline_cache") = "", py::arg("ibl_cache") = "", py::arg("lod_cache") = "",
             py::arg("memory_budget_mib") = 0)
        .def_property_readonly("name", [](PyDevice& self) { return self.with([](candela::Device& d) { return d.name(); }); })
        .def_property_readonly("validation_messages",
                               [](PyDevice& self) { return self.with([](candela::Device& d) { return d.validationMessages(); }); })
        .def_property_readonly("closed", [](const PyDevice& self) { return !self.device.has_value(); })
        .def("close", &PyDevice::close, "Destroys the device (after a render in progress); later calls raise candela.Error.")
        .def("__enter__", [](py::object self) { return self; })
        .def("__exit__", [](PyDevice& self, const py::args&) { self.close(); })
        .def("cancel", [](PyDevice& self) {
            // Not under `busy`: it stops the render that holds it (safe from any thread).
            if (self.device) self.device->cancel();
        }, "Stops a render in progress on another thread (it raises candela.CancelledError).")
        .def("release", [](PyDevice& self) { self.with([](candela::Device& d) { d.release(); }); },
             "Frees the device memory of the last scene drawn.")
        .def("load_scene", [](PyDevice&, const py::object& source, const std::string& name, std::optional<uint32_t> scene) {
            return loadScene(source, name, scene);
        }, py::arg("source"), py::kw_only(), py::arg("name") = "", py::arg("scene") = py::none(), kLoadSceneDoc)
        .def("load_environment", [](PyDevice&, const py::object& source, const std::string& name) {
            return loadEnvironment(source, name);
        }, py::arg("source") = py::none(), py::kw_only(), py::arg("name") = "", kLoadEnvironmentDoc)
        .def("render",
             [](PyDevice& self, const candela::Scene& scene, const py::kwargs& kwargs) {
                 return renderOne(self, scene, renderCall(kwargs, false, nullptr));
             },
             py::arg("scene"), "One image of `scene`: a candela.Frame (docs/python.md lists the keywords).")
        .def("render_sequence",
             [](py::object self, py::object scene, const py::kwargs& kwargs) {
                 SequenceIterator iterator{.device = self, .scene = scene};
                 iterator.call = renderCall(kwargs, true, &iterator.sequence);
                 if (iterator.sequence.views.empty()) {
                     if (iterator.sequence.frames == 0) inputError("an image sequence of 0 frames");
                     if (!(iterator.sequence.fps > 0.0))
                         inputError("an image sequence at " + std::to_string(iterator.sequence.fps) + " frames per second");
                 }
                 py::cast<const candela::Scene&>(scene);  // a TypeError now, not at the first frame
                 return iterator;
             },
             py::arg("scene"), "An iterator over frames of a sequence (frames, fps, turntable, and render's keywords).");
}
