// The Python module meshquilt._meshquilt: the engine the CLI drives, with numpy in and out and no
// files. meshquilt/__init__.py re-exports it with docstrings; meshquilt/__init__.pyi types it.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/error.h"
#include "device.h"
#include "edit/element_edit.h"
#include "edit/swatch_animation.h"
#include "inspect/inspect_report.h"
#include "core/atomic_write.h"
#include "jobs/animate_job.h"
#include "jobs/edit_job.h"
#include "jobs/embed_job.h"
#include "jobs/image_jobs.h"
#include "jobs/loom_job.h"
#include "jobs/synth_job.h"
#include "mesh/base_mesh.h"
#include "mesh/mesh_io.h"
#include "mesh/swatch_frame.h"
#include "mesh/topology.h"
#include "mesh/measures.h"
#include "paint/detail_extraction.h"
#include "paint/surface_paint.h"
#include "paint/surface_relief.h"
#include "quilt/planar_quilting.h"
#include "render/png_encoding.h"
#include "render/render_mesh.h"
#include "shell/shell_embedding.h"
#include "shell/texture_file.h"
#include "shell/texture_placement.h"
#include "surface/guidance_field.h"
#include "surface/surface_quilting.h"
#include "swatch/default_swatch.h"
#include "swatch/swatch_kinds.h"

namespace py = pybind11;
using namespace meshquilt;

namespace {

using Array3d = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Array3i = py::array_t<int32_t, py::array::c_style | py::array::forcecast>;
using Colors = py::array_t<uint8_t, py::array::c_style | py::array::forcecast>;

// The CLI's wording: an option named {name} in a message reads --name.
std::string message_of(const Error& e) {
  return Error::render(e.text(), [](std::string name) {
    std::replace(name.begin(), name.end(), '_', '-');
    return "--" + name;
  });
}

TriMesh mesh_from(const Array3d& vertices, const Array3i& faces, const char* what) {
  if (vertices.ndim() != 2 || vertices.shape(1) != 3)
    throw InputError(std::string(what) + ": vertices must be an (N, 3) array", ErrorKind::invalid_mesh);
  if (faces.ndim() != 2 || faces.shape(1) != 3)
    throw InputError(std::string(what) + ": faces must be an (M, 3) array of vertex indices",
                     ErrorKind::invalid_mesh);
  TriMesh m;
  const auto v = vertices.unchecked<2>();
  const auto f = faces.unchecked<2>();
  for (py::ssize_t i = 0; i < v.shape(0); ++i) m.positions.emplace_back(v(i, 0), v(i, 1), v(i, 2));
  for (py::ssize_t i = 0; i < f.shape(0); ++i) {
    const Tri t{f(i, 0), f(i, 1), f(i, 2)};
    for (int32_t k : t)
      if (k < 0 || static_cast<size_t>(k) >= m.positions.size())
        throw InputError(std::string(what) + ": face " + std::to_string(i) + " indexes vertex " +
                             std::to_string(k) + " of " + std::to_string(m.positions.size()),
                         ErrorKind::invalid_mesh);
    m.triangles.push_back(t);
  }
  return m;
}

// Directions drawn at points over the base, as synth's --field file's `point` entries.
std::vector<FieldConstraint> field_constraints(const Array3d& points, const Array3d& directions, const TriMesh& base) {
  const auto rows = [](const Array3d& a, const char* what) {
    if (a.ndim() != 2 || a.shape(1) != 3)
      throw InputError(std::string("field: ") + what + " must be a (K, 3) array", ErrorKind::invalid_option);
    std::vector<Vec3> out;
    const auto v = a.unchecked<2>();
    for (py::ssize_t i = 0; i < v.shape(0); ++i) out.emplace_back(v(i, 0), v(i, 1), v(i, 2));
    return out;
  };
  return constraints_at_points(rows(points, "points"), rows(directions, "directions"), base, "field");
}

py::array_t<double> positions_array(const std::vector<Vec3>& positions) {
  py::array_t<double> out({static_cast<py::ssize_t>(positions.size()), py::ssize_t{3}});
  auto a = out.mutable_unchecked<2>();
  for (size_t i = 0; i < positions.size(); ++i)
    for (int k = 0; k < 3; ++k) a(i, k) = positions[i][k];
  return out;
}

py::dict dict_of(const TriMesh& m) {
  py::array_t<int32_t> faces({static_cast<py::ssize_t>(m.num_faces()), py::ssize_t{3}});
  auto f = faces.mutable_unchecked<2>();
  for (size_t i = 0; i < m.num_faces(); ++i)
    for (int k = 0; k < 3; ++k) f(i, k) = m.triangles[i][k];
  py::dict out;
  out["vertices"] = positions_array(m.positions);
  out["faces"] = faces;
  const auto ints = [](const std::vector<int32_t>& values) {
    py::array_t<int32_t> a(static_cast<py::ssize_t>(values.size()));
    std::copy(values.begin(), values.end(), a.mutable_data());
    return a;
  };
  out["element"] = ints(m.elements.empty() ? face_components(m) : m.elements);
  if (!m.sources.empty()) out["source"] = ints(m.sources);
  if (!m.origins.empty()) out["origin"] = ints(m.origins);
  if (!m.colors.empty() && m.colors.size() == m.positions.size()) {
    py::array_t<uint8_t> colors({static_cast<py::ssize_t>(m.colors.size()), py::ssize_t{3}});
    auto c = colors.mutable_unchecked<2>();
    for (size_t v = 0; v < m.colors.size(); ++v)
      for (int k = 0; k < 3; ++k) c(v, k) = m.colors[v][k];
    out["colors"] = colors;
  }
  return out;
}

// Per-vertex colours, (N, 3) uint8, onto a mesh of N vertices.
void set_colors(TriMesh& mesh, const std::optional<Colors>& colors, const char* what) {
  if (!colors) return;
  if (colors->ndim() != 2 || colors->shape(1) != 3 || static_cast<size_t>(colors->shape(0)) != mesh.num_vertices())
    throw InputError(std::string(what) + ": colors must be an (N, 3) uint8 array, a row per vertex",
                     ErrorKind::invalid_option);
  const auto c = colors->unchecked<2>();
  mesh.colors.resize(mesh.num_vertices());
  for (size_t v = 0; v < mesh.num_vertices(); ++v) mesh.colors[v] = {c(v, 0), c(v, 1), c(v, 2)};
}

py::object json_to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

// Python's keyword arguments as a registered kind's settings (swatch/swatch_kinds.h); a name the
// kind does not take is passed on, to be refused with the list of those it does.
SwatchSettings swatch_settings(const std::string& kind, const std::string& preset, uint64_t seed,
                               const py::kwargs& kwargs) {
  SwatchSettings settings;
  settings.preset = preset;
  settings.seed = seed;
  const SwatchKind& registered = swatch_kind(kind);
  for (const auto& item : kwargs) {
    const std::string name = py::str(item.first);
    const auto option = std::find_if(registered.options.begin(), registered.options.end(),
                                     [&](const SwatchOption& o) { return o.name == name; });
    if (option == registered.options.end() || option->type == SwatchOption::Type::integer ||
        option->type == SwatchOption::Type::real) {
      settings.numbers[name] = option == registered.options.end() ? 0.0 : item.second.cast<double>();
    } else if (option->type == SwatchOption::Type::text) {
      settings.texts[name] = item.second.cast<std::string>();
    } else if (item.second.cast<bool>()) {
      settings.flags.insert(name);
    }
  }
  check_swatch_settings(kind, settings);
  return settings;
}

std::vector<Vec3> positions_of(const Array3d& a, const char* what) {
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw InputError(std::string("animate: ") + what + " must be an (N, 3) array", ErrorKind::invalid_option);
  std::vector<Vec3> out;
  const auto v = a.unchecked<2>();
  for (py::ssize_t i = 0; i < v.shape(0); ++i) out.emplace_back(v(i, 0), v(i, 1), v(i, 2));
  return out;
}


// Runs `work` without the GIL; a progress callback that raises cancels the job and its error is
// raised here.
struct Job {
  CancelToken own_token;
  CancelToken* token = &own_token;
  std::exception_ptr callback_error;
};

// Seconds left at the pace since the first report: the set-up before it (the layout, the shell,
// grids) is not spread over the rest of the job, which made the first figures run high.
class TimeLeft {
 public:
  double operator()(double share) {
    const auto now = std::chrono::steady_clock::now();
    if (share >= 1.0) return 0.0;
    if (!started_) {
      started_ = true;
      first_ = now;
      first_share_ = share;
      return -1.0;
    }
    const double done = share - first_share_;
    if (!(done > 0.0)) return -1.0;
    return std::chrono::duration<double>(now - first_).count() * (1.0 - share) / done;
  }

 private:
  bool started_ = false;
  std::chrono::steady_clock::time_point first_;
  double first_share_ = 0.0;
};

// Paint's progress (visits made of all) as synth's callback takes it: the share done and the
// seconds left. `callback` outlives the job, and is only called with the GIL held.
std::function<void(size_t, size_t)> paint_progress(const std::optional<py::function>& callback, Job& job) {
  if (!callback) return {};
  const py::function* call = &*callback;
  return [&job, call, time_left = TimeLeft()](size_t done, size_t total) mutable {
    const double share = total > 0 ? std::min(1.0, static_cast<double>(done) / static_cast<double>(total)) : 0.0;
    const double left = time_left(share);
    py::gil_scoped_acquire gil;
    try {
      (*call)(share, left);
    } catch (...) {
      job.callback_error = std::current_exception();
      job.token->cancel();
    }
  };
}

// Runs `work` without the GIL; a callback's error, which cancelled it, is raised in its stead.
template <typename Work>
void run_cancellable(Job& job, Work&& work) {
  {
    py::gil_scoped_release release;
    try {
      work();
    } catch (const Cancelled&) {
      if (!job.callback_error) throw;
    }
  }
  if (job.callback_error) std::rethrow_exception(job.callback_error);
}

}  // namespace

// An (H, W, 3) or, where `grey` allows, (H, W) array of values in [0, 1] as a sample image,
// shrunk to sample_width pixels across (aspect kept) when that is > 0.
ColourImage sample_image(const py::array_t<double, py::array::c_style | py::array::forcecast>& image, const char* what,
                         bool grey, int sample_width) {
  const bool plane = grey && image.ndim() == 2;
  if (!plane && (image.ndim() != 3 || image.shape(2) != 3))
    throw InputError(std::string(what) + (grey ? ": image must be an (H, W) or (H, W, 3) array"
                                               : ": image must be an (H, W, 3) array"),
                     ErrorKind::invalid_option);
  if (image.shape(0) < 1 || image.shape(1) < 1)
    throw InputError(std::string(what) + ": image is empty", ErrorKind::invalid_option);
  ColourImage sample;
  sample.height = static_cast<int>(image.shape(0));
  sample.width = static_cast<int>(image.shape(1));
  const double* pixels = image.data();
  for (size_t k = 0; k < static_cast<size_t>(sample.width) * sample.height; ++k) {
    const glm::dvec3 c = plane ? glm::dvec3(pixels[k]) : glm::dvec3(pixels[3 * k], pixels[3 * k + 1], pixels[3 * k + 2]);
    if (!(glm::all(glm::greaterThanEqual(c, glm::dvec3(0.0))) && glm::all(glm::lessThanEqual(c, glm::dvec3(1.0)))))
      throw InputError(std::string(what) + ": image values must lie in [0, 1]", ErrorKind::invalid_option);
    sample.rgb.push_back(c);
  }
  return sample_width > 0 ? shrunk_to_width(sample, sample_width) : sample;
}

PYBIND11_MODULE(_meshquilt, m) {
  m.doc() = "meshquilt: grows 3D geometric textures over planes and meshes by mesh quilting";
  static py::exception<Error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<Cancelled> cancelled(m, "Cancelled", error.ptr());
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Cancelled& e) {
      cancelled("cancelled");
    } catch (const Error& e) {
      error(message_of(e).c_str());
    }
  });

  py::class_<CancelToken>(m, "CancelToken", "Cancels a running job between stages; the job raises Cancelled.")
      .def(py::init<>())
      .def("cancel", &CancelToken::cancel, "Asks the job to stop.")
      .def_property_readonly("cancelled", &CancelToken::cancelled);

  m.def(
      "swatch",
      [](const std::string& kind, const std::string& preset, uint64_t seed, const py::kwargs& kwargs) {
        return dict_of(make_builtin_swatch(kind, swatch_settings(kind, preset, seed, kwargs)));
      },
      py::arg("kind"), py::arg("preset") = "default", py::arg("seed") = 1);

  m.def("default_swatch", [] { return dict_of(default_swatch()); });

  m.def(
      "synth",
      [](std::optional<Array3d> swatch_vertices, std::optional<Array3i> swatch_faces,
         std::optional<std::pair<double, double>> plane, std::optional<Array3d> base_vertices,
         std::optional<Array3i> base_faces, double scale, uint64_t seed, const std::string& backend,
         int cells, bool cleanup, double fill_margin, int symmetry, double shell_height, const std::string& embed,
         bool per_patch_charts, bool minimize_distortion, bool keep_texture,
         std::optional<py::function> progress, CancelToken* cancel, std::optional<Array3d> field_points,
         std::optional<Array3d> field_directions, double size_hold, double cone_spread) {
        SynthRequest request;
        if (swatch_vertices) {
          request.swatch = mesh_from(*swatch_vertices, *swatch_faces, "swatch");
          request.swatch_name = "swatch";
        }
        if (plane) request.plane = glm::dvec2(plane->first, plane->second);
        if (base_vertices) request.base = mesh_from(*base_vertices, *base_faces, "base");
        request.scale = scale;
        request.seed = seed;
        request.cells = cells;
        request.cleanup = cleanup;
        request.fill_margin = fill_margin;
        request.symmetry = symmetry;
        request.size_hold = size_hold;
        request.cone_spread = cone_spread;
        request.shell_height = shell_height;
        request.embed = embed;
        request.shared_layout = !per_patch_charts;
        request.distortion_min = minimize_distortion;
        request.keep_texture = keep_texture;
        check_synth_request(request);
        if (field_points && !base_vertices)
          throw InputError("synth: a field needs base=(vertices, faces)", ErrorKind::invalid_option);
        const SynthInputs inputs = prepare_synth_inputs(request);
        if (field_points) {
          request.field = field_constraints(*field_points, *field_directions, inputs.base);
          request.field_name = "drawn";
        }
        Job job;
        if (cancel) job.token = cancel;
        SynthHooks hooks;
        hooks.cancel = job.token;
        if (progress) {
          py::function callback = *progress;
          hooks.progress = [&job, callback, time_left = TimeLeft()](const QuiltProgress& p) mutable {
            const double share = p.total_area > 0.0 ? std::min(1.0, p.covered_area / p.total_area) : 0.0;
            const double left = time_left(share);
            py::gil_scoped_acquire gil;
            try {
              callback(share, left);
            } catch (...) {
              job.callback_error = std::current_exception();
              job.token->cancel();
            }
          };
        }
        SynthOutcome outcome;
        {
          py::gil_scoped_release release;
          try {
            std::unique_ptr<engine::Device> device = engine::open_device(engine::parse_backend_choice(backend));
            outcome = run_synth(request, inputs, *device, hooks);
          } catch (const Cancelled&) {
            if (!job.callback_error) throw;
          }
        }
        if (job.callback_error) std::rethrow_exception(job.callback_error);
        const TriMesh& result = outcome.mesh;
        nlohmann::json& stats = outcome.stats;
        stats["output"] = nullptr;  // the mesh comes back as arrays, not a file
        stats["stages"]["write"] = 0.0;
        std::string texture;
        if (keep_texture && request.base)
          texture = format_texture(make_quilt_texture(inputs.base, result, outcome.local, outcome.shell_texture));
        py::dict out = dict_of(result);
        out["stats"] = json_to_python(stats);
        if (!texture.empty()) out["texture"] = py::bytes(texture);
        return out;
      },
      py::arg("swatch_vertices") = py::none(), py::arg("swatch_faces") = py::none(),
      py::arg("plane") = py::none(), py::arg("base_vertices") = py::none(),
      py::arg("base_faces") = py::none(), py::arg("scale") = 0.1, py::arg("seed") = 1,
      py::arg("backend") = "auto", py::arg("cells") = 16, py::arg("cleanup") = true, py::arg("fill_margin") = 0.5, py::arg("symmetry") = 0,
      py::arg("shell_height") = 0.0, py::arg("embed") = "shell", py::arg("per_patch_charts") = false,
      py::arg("minimize_distortion") = true, py::arg("keep_texture") = false,
      py::arg("progress") = py::none(), py::arg("cancel") = nullptr, py::arg("field_points") = py::none(),
      py::arg("field_directions") = py::none(), py::arg("size_hold") = 0.1, py::arg("cone_spread") = 1.5625);

  m.def(
      "guidance",
      [](const Array3d& base_vertices, const Array3i& base_faces, std::optional<Array3d> field_points,
         std::optional<Array3d> field_directions) {
        const TriMesh base = prepare_base(mesh_from(base_vertices, base_faces, "base"), "base");
        const std::vector<FieldConstraint> constraints =
            field_points ? field_constraints(*field_points, *field_directions, base) : std::vector<FieldConstraint>{};
        const BaseSurface surface(base);
        const GuidanceField field = interpolate_field(surface, constraints);
        const auto faces = static_cast<py::ssize_t>(base.num_faces());
        py::array_t<double> centres({faces, py::ssize_t{3}}), directions({faces, py::ssize_t{3}});
        auto c = centres.mutable_unchecked<2>();
        auto d = directions.mutable_unchecked<2>();
        for (py::ssize_t f = 0; f < faces; ++f) {
          const Tri& t = base.triangles[f];
          const Vec3 centre = (base.positions[t[0]] + base.positions[t[1]] + base.positions[t[2]]) / 3.0;
          const Vec3 along = field.at(surface, SurfacePoint{static_cast<int32_t>(f), glm::dvec2(1.0 / 3.0)});
          for (int k = 0; k < 3; ++k) {
            c(f, k) = centre[k];
            d(f, k) = along[k];
          }
        }
        return py::make_tuple(centres, directions);
      },
      py::arg("base_vertices"), py::arg("base_faces"), py::arg("field_points") = py::none(),
      py::arg("field_directions") = py::none());

  m.def(
      "paint",
      [](const Array3d& base_vertices, const Array3i& base_faces,
         const py::array_t<double, py::array::c_style | py::array::forcecast>& image, double scale,
         double pixels_per_unit, int window, int passes, double coherence, uint64_t seed, const std::string& backend,
         std::optional<py::function> progress, CancelToken* cancel, std::optional<Array3d> field_points,
         std::optional<Array3d> field_directions, int sample_width) {
        const auto start = std::chrono::steady_clock::now();
        const ColourImage sample = sample_image(image, "paint", false, sample_width);
        const TriMesh base = prepare_base(mesh_from(base_vertices, base_faces, "base"), "base");
        const std::vector<FieldConstraint> constraints =
            field_points ? field_constraints(*field_points, *field_directions, base) : std::vector<FieldConstraint>{};
        PaintOptions options;
        options.pixels_per_unit = sample_pixels_per_unit(base, sample.width, scale, pixels_per_unit);
        options.window = window;
        options.passes = passes;
        options.coherence = coherence;
        options.seed = seed;
        Job job;
        if (cancel) job.token = cancel;
        options.progress = paint_progress(progress, job);
        options.cancel = job.token;
        const std::unique_ptr<engine::Device> device = engine::open_device(engine::parse_backend_choice(backend));
        PaintResult painted;
        run_cancellable(job, [&] { painted = paint_surface(base, sample, constraints, options, *device); });
        py::dict out = dict_of(painted.mesh);
        nlohmann::json stats = paint_stats(painted, options, sample, *device);
        stats["base"] = stats["image"] = stats["output"] = nullptr;  // arrays, not files
        stats["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        out["stats"] = json_to_python(stats);
        return out;
      },
      py::arg("base_vertices"), py::arg("base_faces"), py::arg("image"), py::arg("scale") = 0.25,
      py::arg("pixels_per_unit") = 0.0, py::arg("window") = 7, py::arg("passes") = 2, py::arg("coherence") = 2.0,
      py::arg("seed") = 1, py::arg("backend") = "auto", py::arg("progress") = py::none(), py::arg("cancel") = nullptr,
      py::arg("field_points") = py::none(), py::arg("field_directions") = py::none(), py::arg("sample_width") = 0);

  m.def(
      "relief",
      [](const Array3d& base_vertices, const Array3i& base_faces,
         const std::optional<py::array_t<double, py::array::c_style | py::array::forcecast>>& image, double height,
         std::optional<Array3d> model_vertices, std::optional<Array3i> model_faces,
         std::optional<std::vector<double>> region, double smoothing, int pixels, double scale, double pixels_per_unit,
         int window, int passes, double coherence, uint64_t seed, const std::string& backend, double clearance,
         std::optional<py::function> progress, CancelToken* cancel,
         std::optional<Array3d> field_points, std::optional<Array3d> field_directions, int sample_width) {
        const auto start = std::chrono::steady_clock::now();
        if (image.has_value() == model_vertices.has_value())
          throw InputError("relief: expected one of image and model", ErrorKind::invalid_option);
        if (image && !(height > 0.0)) throw InputError("relief: height is required with an image", ErrorKind::invalid_option);
        const TriMesh base = prepare_base(mesh_from(base_vertices, base_faces, "base"), "base");
        const std::vector<FieldConstraint> constraints =
            field_points ? field_constraints(*field_points, *field_directions, base) : std::vector<FieldConstraint>{};
        ReliefOptions options;
        options.clearance = clearance;
        options.height = height;
        ColourImage sample;
        nlohmann::json from;
        if (image) {
          sample = sample_image(*image, "relief", true, sample_width);
          options.paint.pixels_per_unit = sample_pixels_per_unit(base, sample.width, scale, pixels_per_unit);
        } else {
          if (!model_faces) throw InputError("relief: model needs its faces", ErrorKind::invalid_option);
          const TriMesh model = prepare_base(mesh_from(*model_vertices, *model_faces, "model"), "model");
          if (region && region->size() != 4)
            throw InputError("relief: region must be (x, y, z, radius) in model units", ErrorKind::invalid_option);
          std::optional<DetailRegion> ball;
          if (region) ball = DetailRegion{Vec3((*region)[0], (*region)[1], (*region)[2]), (*region)[3]};
          const ModelSample made = model_sample(model, smoothing, ball, pixels, base, scale, pixels_per_unit);
          sample = made.image;
          options.paint.pixels_per_unit = made.pixels_per_unit;
          if (!(height > 0.0)) options.height = made.height;  // heights scale as widths do
          from = made.from;
          from["model"] = nullptr;
        }
        options.paint.window = window;
        options.paint.passes = passes;
        options.paint.coherence = coherence;
        options.paint.seed = seed;
        Job job;
        if (cancel) job.token = cancel;
        options.paint.progress = paint_progress(progress, job);
        options.paint.cancel = job.token;
        const std::unique_ptr<engine::Device> device = engine::open_device(engine::parse_backend_choice(backend));
        ReliefResult relief;
        run_cancellable(job, [&] { relief = relief_surface(base, sample, constraints, options, *device); });
        py::dict out = dict_of(relief.mesh);
        py::array_t<double> heights(static_cast<py::ssize_t>(relief.heights.size()));
        std::copy(relief.heights.begin(), relief.heights.end(), heights.mutable_data());
        out["heights"] = heights;
        nlohmann::json stats = relief_stats(relief, options, *device);
        stats["base"] = stats["image"] = stats["output"] = nullptr;  // arrays, not files
        stats["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!from.is_null()) stats["from"] = from;
        out["stats"] = json_to_python(stats);
        return out;
      },
      py::arg("base_vertices"), py::arg("base_faces"), py::arg("image") = py::none(), py::arg("height") = 0.0,
      py::arg("model_vertices") = py::none(), py::arg("model_faces") = py::none(), py::arg("region") = py::none(),
      py::arg("smoothing") = 0.0, py::arg("pixels") = 32, py::arg("scale") = 0.25, py::arg("pixels_per_unit") = 0.0,
      py::arg("window") = 7, py::arg("passes") = 2, py::arg("coherence") = 2.0, py::arg("seed") = 1,
      py::arg("backend") = "auto",
      py::arg("clearance") = 0.4, py::arg("progress") = py::none(), py::arg("cancel") = nullptr,
      py::arg("field_points") = py::none(), py::arg("field_directions") = py::none(), py::arg("sample_width") = 0);

  m.def(
      "embed",
      [](const py::bytes& texture_bytes, const Array3d& base_vertices, const Array3i& base_faces,
         const std::string& embed) {
        const auto start = std::chrono::steady_clock::now();
        const QuiltTexture texture = parse_texture(std::string(texture_bytes), "texture");
        const TriMesh base = prepare_base(mesh_from(base_vertices, base_faces, "base"), "base");
        PlacedTexture placed;
        {
          py::gil_scoped_release release;
          placed = run_embed(texture, base, embed, "texture", "base");
        }
        nlohmann::json stats = {{"texture", nullptr}, {"base", nullptr}, {"output", nullptr}};
        stats.update(embed_stats(placed));
        stats["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        py::dict out = dict_of(placed.mesh);
        out["stats"] = json_to_python(stats);
        return out;
      },
      py::arg("texture"), py::arg("base_vertices"), py::arg("base_faces"), py::arg("embed") = "auto");

  m.def(
      "read",
      [](const std::string& path) {
        TriMesh mesh;
        {
          py::gil_scoped_release release;
          mesh = read_mesh(path);
        }
        return dict_of(mesh);
      },
      py::arg("path"));

  m.def(
      "write",
      [](const Array3d& vertices, const Array3i& faces, std::optional<py::array_t<int32_t>> element,
         std::optional<py::array_t<int32_t>> source, const std::string& path, std::optional<Colors> colors) {
        TriMesh mesh = mesh_from(vertices, faces, "write");
        if (element) mesh.elements.assign(element->data(), element->data() + element->size());
        if (source) mesh.sources.assign(source->data(), source->data() + source->size());
        set_colors(mesh, colors, "write");
        if ((!mesh.elements.empty() && mesh.elements.size() != mesh.num_faces()) ||
            (!mesh.sources.empty() && mesh.sources.size() != mesh.num_faces()))
          throw InputError("write: element and source need one entry per face", ErrorKind::invalid_option);
        py::gil_scoped_release release;
        write_mesh(mesh, path);
      },
      py::arg("vertices"), py::arg("faces"), py::arg("element") = py::none(), py::arg("source") = py::none(),
      py::arg("path"), py::arg("colors") = py::none());

  m.def(
      "inspect",
      [](const Array3d& vertices, const Array3i& faces, std::optional<py::array_t<int32_t>> element) {
        TriMesh mesh = mesh_from(vertices, faces, "inspect");
        if (element) mesh.elements.assign(element->data(), element->data() + element->size());
        InspectReport report;
        {
          py::gil_scoped_release release;
          report = inspect_mesh(mesh);
        }
        return json_to_python(to_json(report));
      },
      py::arg("vertices"), py::arg("faces"), py::arg("element") = py::none());

  m.def(
      "render",
      [](const Array3d& vertices, const Array3i& faces, std::optional<py::array_t<int32_t>> element,
         const std::string& path, int width, int height, const std::string& mode, std::optional<Colors> colors,
         const std::string& view, const std::string& up, std::optional<std::vector<double>> around, double radius) {
        TriMesh mesh = mesh_from(vertices, faces, "render");
        if (element) mesh.elements.assign(element->data(), element->data() + element->size());
        set_colors(mesh, colors, "render");
        RenderOptions options;
        options.width = width;
        options.height = height;
        options.mode = parse_render_mode(mode);
        options.view = parse_view(view);
        options.up = parse_up_axis(up);
        if (around) {
          if (around->size() != 3) throw InputError("{around}: expected a point (x, y, z)", ErrorKind::invalid_option);
          options.close_up = CloseUp{Vec3((*around)[0], (*around)[1], (*around)[2]), radius};
        }
        py::gil_scoped_release release;
        write_file_atomic(path, encode_png(render_mesh(mesh, options)));
      },
      py::arg("vertices"), py::arg("faces"), py::arg("element") = py::none(), py::arg("path"),
      py::arg("width") = 1024, py::arg("height") = 768, py::arg("mode") = "shaded", py::arg("colors") = py::none(),
      py::arg("view") = "oblique", py::arg("up") = "z", py::arg("around") = py::none(), py::arg("radius") = 0.0);

  m.def(
      "edit",
      [](const Array3d& vertices, const Array3i& faces, const py::array_t<int32_t>& element,
         std::optional<py::array_t<int32_t>> source, std::vector<int32_t> remove_elements,
         std::vector<int32_t> remove_sources, std::vector<int32_t> keep_sources,
         std::optional<std::vector<double>> remove_box, std::optional<std::vector<double>> remove_sphere, double age,
         uint64_t seed, const std::string& color_by, const std::string& palette) {
        const auto start = std::chrono::steady_clock::now();
        TriMesh mesh = mesh_from(vertices, faces, "edit");
        mesh.elements.assign(element.data(), element.data() + element.size());
        if (source) mesh.sources.assign(source->data(), source->data() + source->size());
        EditRequest request;
        request.remove_elements = std::move(remove_elements);
        request.remove_sources = std::move(remove_sources);
        request.keep_sources = std::move(keep_sources);
        if (remove_box) request.remove_inside.push_back(box_region(*remove_box));
        if (remove_sphere) request.remove_inside.push_back(sphere_region(*remove_sphere));
        request.age = age;
        request.seed = seed;
        const bool recolour = !color_by.empty() || !palette.empty();
        const ColorBy by = color_by.empty() ? ColorBy::element : parse_color_by(color_by);
        const auto colours = palette.empty() ? std::vector<std::array<uint8_t, 3>>{} : parse_palette(palette);
        const EditOutcome edit = plan_edit(mesh, request, "edit");
        TriMesh kept = keep_faces(mesh, edit.keep);
        if (recolour) kept.colors = vertex_colors(kept, by, colours);
        nlohmann::json stats = {{"input", nullptr}, {"output", nullptr}};
        stats.update(edit_stats(edit.counts));
        stats["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        py::dict out = dict_of(kept);
        out["removed"] = edit.removed;
        out["stats"] = json_to_python(stats);
        return out;
      },
      py::arg("vertices"), py::arg("faces"), py::arg("element"), py::arg("source") = py::none(),
      py::arg("remove_elements") = std::vector<int32_t>{}, py::arg("remove_sources") = std::vector<int32_t>{},
      py::arg("keep_sources") = std::vector<int32_t>{}, py::arg("remove_box") = py::none(),
      py::arg("remove_sphere") = py::none(), py::arg("age") = 0.0, py::arg("seed") = 1, py::arg("color_by") = "",
      py::arg("palette") = "");

  m.def(
      "loom",
      [](const py::array_t<double, py::array::c_style | py::array::forcecast>& design,
         const std::vector<std::tuple<Array3d, Array3i, std::optional<py::array_t<int32_t>>>>& exemplars,
         const std::string& method, uint64_t seed, int stations, int sides, const std::string& weaves,
         std::optional<py::array_t<double, py::array::c_style | py::array::forcecast>> warp_colors,
         std::optional<py::array_t<double, py::array::c_style | py::array::forcecast>> weft_colors,
         bool assignment_only) {
        const auto start = std::chrono::steady_clock::now();
        LoomRequest request;
        request.design = sample_image(design, "loom: design", true, 0);
        request.method = parse_assignment_method(method);
        request.seed = seed;
        request.stations = stations;
        request.sides = sides;
        request.assignment_only = assignment_only;
        if (!weaves.empty()) request.weaves = parse_colour_weaves(weaves);
        if (warp_colors) request.warp_types = sample_image(*warp_colors, "loom: warp_colors", false, 0);
        if (weft_colors) request.weft_types = sample_image(*weft_colors, "loom: weft_colors", false, 0);
        for (size_t u = 0; u < exemplars.size(); ++u) {
          const auto& [vertices, faces, element] = exemplars[u];
          const std::string name = "exemplar " + std::to_string(u);
          TriMesh mesh = mesh_from(vertices, faces, name.c_str());
          if (element) mesh.elements.assign(element->data(), element->data() + element->size());
          request.exemplars.push_back(std::move(mesh));
          request.exemplar_names.push_back(name);
        }
        check_loom_request(request);
        LoomOutcome outcome;
        {
          py::gil_scoped_release release;
          outcome = run_loom(request);
        }
        nlohmann::json stats = {{"design_file", nullptr}, {"output", nullptr}};
        stats.update(outcome.stats);
        stats["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const LoomAssignment& a = outcome.assignment;
        py::array_t<int32_t> blocks({a.rows, a.columns, 3});
        int32_t* b = blocks.mutable_data();
        for (const LoomBlock& block : a.blocks) {
          *b++ = block.exemplar;
          *b++ = block.x;
          *b++ = block.y;
        }
        py::dict out = assignment_only ? py::dict() : dict_of(outcome.fabric.mesh);
        out["stats"] = json_to_python(stats);
        out["assignment"] = blocks;
        return out;
      },
      py::arg("design"), py::arg("exemplars"), py::arg("method") = "structured", py::arg("seed") = 1,
      py::arg("stations") = 8, py::arg("sides") = 8, py::arg("weaves") = "", py::arg("warp_colors") = py::none(),
      py::arg("weft_colors") = py::none(), py::arg("assignment_only") = false);

  m.def("swatch_kinds", [] {
    py::list kinds;
    for (const SwatchKind& kind : swatch_kinds()) {
      py::list options;
      for (const SwatchOption& o : kind.options) {
        static const char* types[] = {"integer", "real", "text", "flag"};
        options.append(py::dict(py::arg("name") = o.name, py::arg("type") = types[static_cast<int>(o.type)],
                                py::arg("help") = Error::render(o.help, [](const std::string& n) { return n; }), py::arg("choices") = o.choices));
      }
      kinds.append(py::dict(py::arg("name") = kind.name, py::arg("help") = Error::render(kind.help, [](const std::string& n) { return n; }),
                            py::arg("random") = kind.random, py::arg("options") = options,
                            py::arg("defaults") = kind.defaults("default"),
                            py::arg("small_defaults") = kind.defaults("small")));
    }
    return kinds;
  });

  m.def(
      "vine_frames",
      [](int count, const std::string& preset, uint64_t seed, const py::kwargs& kwargs) {
        const SwatchSettings settings = swatch_settings("vine", preset, seed, kwargs);
        if (count < 1 || count > 10000)
          throw InputError("{frames}: expected 1..10000, got " + std::to_string(count), ErrorKind::invalid_option);
        py::list frames;
        for (const TriMesh& frame : swatch_kind("vine").frames(settings, count))
          frames.append(positions_array(frame.positions));
        return frames;
      },
      py::arg("count"), py::arg("preset") = "default", py::arg("seed") = 1);

  m.def(
      "animate",
      [](const Array3d& vertices, const Array3i& faces, const py::array_t<int32_t>& element,
         const py::array_t<int32_t>& origin, const Array3d& swatch_rest, const std::vector<Array3d>& swatch_frames,
         bool keep_all) {
        const auto start = std::chrono::steady_clock::now();
        TriMesh quilt = mesh_from(vertices, faces, "animate");
        quilt.elements.assign(element.data(), element.data() + element.size());
        quilt.origins.assign(origin.data(), origin.data() + origin.size());
        check_animated_quilt(quilt, "animate");
        const std::vector<Vec3> rest = positions_of(swatch_rest, "swatch_rest");
        std::vector<std::vector<Vec3>> frames;
        for (const Array3d& frame : swatch_frames) {
          frames.push_back(positions_of(frame, "a swatch frame"));
          check_swatch_frame(frames.back().size(), rest.size(), "animate: swatch frame " +
                             std::to_string(frames.size() - 1), "swatch_rest");
        }
        std::vector<std::vector<Vec3>> moved;
        MeetingElements meeting;
        {
          py::gil_scoped_release release;
          const std::vector<glm::dmat3> local = vertex_frames(quilt, rest);
          for (const std::vector<Vec3>& frame : frames) moved.push_back(animated_positions(quilt, local, rest, frame));
          meeting = meeting_elements(quilt, keep_all ? 0 : moved.size(), [&](size_t k) { return moved[k]; });
        }
        nlohmann::json stats = {{"quilt", nullptr}};
        stats.update(animate_stats(moved.size(), meeting));
        stats["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        stats["per_frame"] = nlohmann::json::array();
        const std::vector<int32_t>& dropped = meeting.dropped;
        py::list positions;
        for (const std::vector<Vec3>& frame : moved) positions.append(positions_array(frame));
        py::dict out;
        out["frames"] = positions;
        out["dropped"] = dropped;
        out["stats"] = json_to_python(stats);
        return out;
      },
      py::arg("vertices"), py::arg("faces"), py::arg("element"), py::arg("origin"), py::arg("swatch_rest"),
      py::arg("swatch_frames"), py::arg("keep_all") = false);
}
