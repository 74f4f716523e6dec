// `meshquilt render MESH -o OUT.png [--view V] [--mode M] [--size WxH] [--up A] [--around X,Y,Z
// [--radius R]]`: a preview image.
#include "render_command.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <memory>

#include "atomic_file.h"
#include "commands.h"
#include "core/error.h"
#include "mesh/mesh_io.h"
#include "render/png_encoding.h"

namespace meshquilt::cli {
namespace {

struct RenderArgs {
  std::string mesh;
  std::string output;
  std::string view = "oblique";
  std::string mode = "shaded";
  std::string size = "1024x768";
  std::string up = "z";
  std::string around;
  double radius = 0.0;
  bool radius_given = false;
};

// "X,Y,Z": three finite numbers.
Vec3 parse_point(const std::string& text) {
  double xyz[3];
  const char* at = text.data();
  const char* end = text.data() + text.size();
  for (int k = 0; k < 3; ++k) {
    const auto [ptr, ec] = std::from_chars(at, end, xyz[k]);
    const bool last = k == 2;
    if (ec != std::errc() || !std::isfinite(xyz[k]) || (last ? ptr != end : (ptr == end || *ptr != ',')))
      throw InputError("--around: expected a point X,Y,Z, got '" + text + "'", ErrorKind::invalid_option);
    at = ptr + 1;
  }
  return {xyz[0], xyz[1], xyz[2]};
}

void check_png_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".png")
    throw IoError(ErrorKind::unknown_format, file.string() + ": unknown image format (use .png)");
}

bool parse_side(const std::string& text, int* side) {
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, *side);
  return ec == std::errc() && ptr == end && !text.empty();
}

void run_render(const RenderArgs& args) {
  RenderOptions options;
  parse_image_size(args.size, &options);
  options.view = parse_view(args.view);
  options.mode = parse_render_mode(args.mode);
  options.up = parse_up_axis(args.up);
  const std::filesystem::path output(args.output);
  check_png_extension(output);
  check_writable(output);
  if (args.radius_given && args.around.empty())
    throw InputError("--radius: needs --around X,Y,Z", ErrorKind::invalid_option);
  if (args.radius_given && !(args.radius > 0.0 && std::isfinite(args.radius)))
    throw InputError("--radius: expected a positive distance, got " + std::to_string(args.radius),
                     ErrorKind::invalid_option);
  if (!args.around.empty()) options.close_up = CloseUp{parse_point(args.around), args.radius_given ? args.radius : 0.0};
  const TriMesh mesh = read_mesh(args.mesh);
  try {
    write_preview(mesh, output, options);
  } catch (const InputError& e) {
    if (!options.close_up || e.kind() != ErrorKind::invalid_mesh) throw;
    // Nothing near the point: name the file and the point as given.
    char radius[32];
    std::snprintf(radius, sizeof radius, "%g", close_up_radius(mesh, *options.close_up));
    throw InputError(args.mesh + ": no element within " + radius + " of --around " + args.around,
                     ErrorKind::invalid_mesh);
  }
  std::printf("wrote %s: %dx%d, %zu faces, %s view, %s\n", output.string().c_str(), options.width,
              options.height, mesh.num_faces(), args.view.c_str(), args.mode.c_str());
}

}  // namespace

void write_preview(const TriMesh& mesh, const std::filesystem::path& png, const RenderOptions& options) {
  check_png_extension(png);
  check_writable(png);
  write_text_atomic(png, encode_png(render_mesh(mesh, options)));
}

void parse_image_size(const std::string& text, RenderOptions* options) {
  const size_t x = text.find_first_of("xX");
  int width = 0, height = 0;
  if (x == std::string::npos || !parse_side(text.substr(0, x), &width) ||
      !parse_side(text.substr(x + 1), &height))
    throw InputError("--size: expected WxH in pixels (e.g. 1024x768), got '" + text + "'",
                     ErrorKind::invalid_option);
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
    throw InputError(
        "--size " + text + ": each side must be 1 to " + std::to_string(kMaxImageSide) + " pixels",
        ErrorKind::invalid_option);
  options->width = width;
  options->height = height;
}

void add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand(
      "render",
      "Write a preview PNG of a mesh: orthographic, ray cast on the CPU, framed on its bounding box");
  cmd->add_option("MESH", args->mesh, "mesh to render (.obj .ply .off .stl)")->required();
  cmd->add_option("-o,--output", args->output, "output image (.png)")->required();
  cmd->add_option("--view", args->view,
                  "top|oblique|front|side (oblique: 35 degrees down from the front right)")
      ->capture_default_str();
  cmd->add_option("--mode", args->mode,
                  "shaded: grey-blue, lightly tinted per element; elements: one flat colour per element; colors: the vertex colours")
      ->capture_default_str();
  cmd->add_option("--size", args->size, "image size WxH in pixels, each side at most 8192")
      ->capture_default_str();
  cmd->add_option("--up", args->up, "x|y|z: the mesh's axis shown upward (y for y-up scans such as bunny.off)")
      ->capture_default_str();
  cmd->add_option("--around", args->around,
                  "X,Y,Z: a close-up of the elements within --radius of this point (such as a cone of the "
                  "stats' cone_points), seen from outside along the line to the mesh's centre");
  cmd->add_option("--radius", args->radius, "with --around: how far from the point (default: a tenth of the mesh's diagonal)")
      ->each([args](const std::string&) { args->radius_given = true; });
  cmd->callback([args] { run_render(*args); });
}

}  // namespace meshquilt::cli
