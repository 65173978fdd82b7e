// _prism: the library's public API (core/api/prism.h) for Python. The
// package python/prism/__init__.py wraps it; users import `prism`
// (docs/python.md). Pictures cross as NumPy arrays: a render's radiance is
// handed over without a copy (the array owns the C++ image), pictures coming
// back from Python (expose, write) are copied once.
#include "ray_tree_dict.h"
#include "render_call.h"

#include "core/api/prism.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <cstring>
#include <optional>
#include <string>

namespace py = pybind11;

namespace prism::python {

namespace {

using Triple = std::array<double, 3>;

Vec3 vec(const Triple& t) { return Vec3(t[0], t[1], t[2]); }

// A scene and how many renders are reading it: the C++ scene may be read by
// several renders at once but not edited meanwhile (core/api/prism.h), so
// an edit during a render (from another thread, or a progress callback) is
// refused rather than raced. The count changes only with the GIL held.
struct PyScene {
  api::LoadedScene scene;
  int renders = 0;

  api::LoadedScene& forEdit() {
    if (renders > 0)
      throw std::runtime_error("the scene is being rendered: edit it when the render has ended");
    return scene;
  }
};

// Counts a render of `s` while it lives.
class Reading {
public:
  explicit Reading(PyScene& s) : s_(s) { ++s_.renders; }
  ~Reading() { --s_.renders; }
  Reading(const Reading&) = delete;
  Reading& operator=(const Reading&) = delete;

private:
  PyScene& s_;
};

api::RenderOptions renderOptions(int width, int height, int depth, double thresh, bool antialias,
                                 bool jitter, double bailout, int threads) {
  api::RenderOptions o;
  o.width = width;
  o.height = height;
  o.depth = depth;
  o.thresh = thresh;
  o.antialias = antialias;
  o.jitter = jitter;
  o.bailout = bailout;
  o.threads = threads;
  return o;
}

static_assert(sizeof(Rgb) == 3 * sizeof(float), "a pixel is three packed floats");

// (radiance float32 (H, W, 3), supersampled uint8 (H, W), avgmax, statistics
// as JSON): both arrays view the image, which lives as long as either.
py::tuple imageTuple(api::Image&& rendered) {
  auto* image = new api::Image(std::move(rendered));
  const py::capsule owner(image, [](void* p) { delete static_cast<api::Image*>(p); });
  const auto h = py::ssize_t(image->height), w = py::ssize_t(image->width);
  const auto f = py::ssize_t(sizeof(float));
  py::array_t<float> radiance({h, w, py::ssize_t(3)}, {w * 3 * f, 3 * f, f},
                              reinterpret_cast<const float*>(image->radiance.data()), owner);
  py::array_t<std::uint8_t> supersampled({h, w}, {w, py::ssize_t(1)}, image->supersampled.data(),
                                         owner);
  return py::make_tuple(radiance, supersampled, image->avgmax, api::statsJson(*image));
}

// A picture from Python, (H, W, 3) of anything that converts to float32.
api::Image imageFrom(const py::array_t<float, py::array::c_style | py::array::forcecast>& radiance,
                     double avgmax) {
  if (radiance.ndim() != 3 || radiance.shape(2) != 3 || radiance.shape(0) < 1 ||
      radiance.shape(1) < 1)
    throw std::invalid_argument("the picture must be an array of shape (height, width, 3)");
  api::Image image;
  image.height = int(radiance.shape(0));
  image.width = int(radiance.shape(1));
  image.radiance.resize(std::size_t(image.width) * std::size_t(image.height));
  std::memcpy(image.radiance.data(), radiance.data(), image.radiance.size() * sizeof(Rgb));
  image.avgmax = avgmax;
  return image;
}

py::dict cameraDict(const CameraSpec& c) {
  py::dict d;
  d["eye"] = tupleOf(c.eye);
  d["lookat"] = tupleOf(c.lookat);
  d["up"] = tupleOf(c.up);
  d["fov"] = c.fov;
  return d;
}

py::list lightList(const std::vector<Light>& lights) {
  py::list list;
  for (const Light& l : lights)
    list.append(py::make_tuple(tupleOf(l.position), tupleOf(l.intensity)));
  return list;
}

// Light `index` (0-based) of `s`, with what is given changed.
Light editedLight(const PyScene& s, std::size_t index, const std::optional<Triple>& position,
                  const std::optional<Triple>& intensity) {
  const std::vector<Light>& lights = s.scene.lights();
  if (index >= lights.size())
    throw std::out_of_range("there is no light " + std::to_string(index) + " (the scene has " +
                            std::to_string(lights.size()) + ")");
  Light light = lights[index];
  if (position) light.position = vec(*position);
  if (intensity) light.intensity = vec(*intensity);
  return light;
}

void bindScene(py::module_& m) {
  py::class_<PyScene>(m, "Scene", "A scene read and ready to render (prism.load, prism.parse).")
      .def("__repr__",
           [](const PyScene& s) {
             return "<prism.Scene '" + s.scene.name() + "' " + std::to_string(s.scene.width()) +
                    " x " + std::to_string(s.scene.height()) +
                    " primitives=" + std::to_string(s.scene.scene().primitiveCount()) +
                    " lights=" + std::to_string(s.scene.lights().size()) + ">";
           })
      .def_property_readonly("name", [](const PyScene& s) { return s.scene.name(); })
      .def_property_readonly("width", [](const PyScene& s) { return s.scene.width(); })
      .def_property_readonly("height", [](const PyScene& s) { return s.scene.height(); })
      .def_property_readonly("warnings", [](const PyScene& s) { return s.scene.warnings(); })
      .def_property_readonly("primitives",
                             [](const PyScene& s) { return s.scene.scene().primitiveCount(); })
      .def_property_readonly("camera",
                             [](const PyScene& s) { return cameraDict(s.scene.camera()); })
      .def(
          "set_camera",
          [](PyScene& s, const std::optional<Triple>& eye, const std::optional<Triple>& lookat,
             const std::optional<Triple>& up, std::optional<double> fov) {
            CameraSpec c = s.scene.camera();
            if (eye) c.eye = vec(*eye);
            if (lookat) c.lookat = vec(*lookat);
            if (up) c.up = vec(*up);
            if (fov) c.fov = *fov;
            s.forEdit().setCamera(c);
          },
          py::kw_only(), py::arg("eye") = py::none(), py::arg("lookat") = py::none(),
          py::arg("up") = py::none(), py::arg("fov") = py::none())
      .def_property_readonly("lights", [](const PyScene& s) { return lightList(s.scene.lights()); })
      .def(
          "set_light",
          [](PyScene& s, std::size_t index, const std::optional<Triple>& position,
             const std::optional<Triple>& intensity) {
            s.forEdit().setLight(index, editedLight(s, index, position, intensity));
          },
          py::arg("index"), py::kw_only(), py::arg("position") = py::none(),
          py::arg("intensity") = py::none())
      .def(
          "add_light",
          [](PyScene& s, const Triple& position, const Triple& intensity) {
            s.forEdit().addLight(Light{vec(position), vec(intensity)});
          },
          py::arg("position"), py::arg("intensity"))
      .def(
          "remove_light", [](PyScene& s, std::size_t index) { s.forEdit().removeLight(index); },
          py::arg("index"));
}

PyScene load(const std::filesystem::path& path) {
  const py::gil_scoped_release release;
  return PyScene{api::LoadedScene::fromFile(path)};
}

PyScene parse(const std::string& text, const std::string& name) {
  const py::gil_scoped_release release;
  return PyScene{api::LoadedScene::fromText(text, name)};
}

py::tuple render(PyScene& s, int width, int height, int depth, double thresh, bool antialias,
                 bool jitter, double bailout, int threads, const py::object& progress) {
  const Reading reading(s);
  return imageTuple(renderFromPython(
      s.scene, renderOptions(width, height, depth, thresh, antialias, jitter, bailout, threads),
      progress));
}

// (the tree as dicts, the printout of `prism render --pixel`).
py::tuple rayTree(PyScene& s, int x, int y, int width, int height, int depth, double bailout) {
  const Reading reading(s);
  api::RenderOptions o;
  o.width = width;
  o.height = height;
  o.depth = depth;
  o.bailout = bailout;
  std::string text;
  RayTreeNode root;
  {
    const py::gil_scoped_release release;
    root = api::pixelRayTree(s.scene, o, x, y, &text);
  }
  return py::make_tuple(rayTreeDict(root, s.scene.scene()), text);
}

py::array_t<std::uint8_t>
exposePicture(const py::array_t<float, py::array::c_style | py::array::forcecast>& radiance,
              double avgmax, bool srgb) {
  const api::Image image = imageFrom(radiance, avgmax);
  std::vector<std::uint8_t> bytes;
  {
    const py::gil_scoped_release release;
    bytes = api::expose(image, srgb); // by image.avgmax
  }
  py::array_t<std::uint8_t> out(
      {py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(3)});
  std::memcpy(out.mutable_data(), bytes.data(), bytes.size());
  return out;
}

void writePicture(const std::filesystem::path& path,
                  const py::array_t<float, py::array::c_style | py::array::forcecast>& radiance,
                  double avgmax, bool srgb, bool floatRadiance) {
  const api::Image image = imageFrom(radiance, avgmax);
  api::WriteOptions options;
  options.srgb = srgb;
  options.floatRadiance = floatRadiance;
  const py::gil_scoped_release release;
  api::write(path, image, options);
}

py::list diagnosticList(const SceneError& e) {
  py::list list;
  for (const Diagnostic& d : e.diagnostics())
    list.append(py::make_tuple(d.file, d.line, d.column, d.message));
  return list;
}

} // namespace

} // namespace prism::python

PYBIND11_MODULE(_prism, m) {
  using namespace prism::python;
  m.doc() = "Prism's library API (core/api/prism.h); use the package `prism`, which wraps it.";

  // prism::SceneError: a ValueError whose message is the located errors,
  // one "FILE:LINE:COLUMN: error: ..." line each, and whose `diagnostics`
  // holds them as (file, line, column, message).
  static py::exception<prism::SceneError> sceneError(m, "SceneError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const prism::SceneError& e) {
      py::object error = py::reinterpret_borrow<py::object>(sceneError)(e.what());
      error.attr("diagnostics") = diagnosticList(e);
      PyErr_SetObject(sceneError.ptr(), error.ptr());
    }
  });

  bindScene(m);
  m.def("load", &load, py::arg("path"));
  m.def("parse", &parse, py::arg("text"), py::arg("name") = "<string>");
  m.def("render", &render, py::arg("scene"), py::kw_only(), py::arg("width"), py::arg("height"),
        py::arg("depth"), py::arg("thresh"), py::arg("antialias"), py::arg("jitter"),
        py::arg("bailout"), py::arg("threads"), py::arg("progress"));
  m.def("ray_tree", &rayTree, py::arg("scene"), py::arg("x"), py::arg("y"), py::kw_only(),
        py::arg("width"), py::arg("height"), py::arg("depth"), py::arg("bailout"));
  m.def("expose", &exposePicture, py::arg("radiance"), py::kw_only(), py::arg("avgmax"),
        py::arg("srgb"));
  m.def("write", &writePicture, py::arg("path"), py::arg("radiance"), py::kw_only(),
        py::arg("avgmax"), py::arg("srgb"), py::arg("float_radiance"));
}
