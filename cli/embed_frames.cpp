#include "embed_frames.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>
#include <vector>

#include "atomic_file.h"
#include "core/error.h"
#include "mesh/base_mesh.h"
#include "mesh/mesh_io.h"
#include "sha256.h"
#include "shell/texture_file.h"
#include "shell/texture_placement.h"

namespace meshquilt::cli {
namespace {

namespace fs = std::filesystem;

// Natural order: runs of digits compare as numbers, so frame2 comes before frame10.
bool natural_less(const std::string& a, const std::string& b) {
  size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (std::isdigit(static_cast<unsigned char>(a[i])) && std::isdigit(static_cast<unsigned char>(b[j]))) {
      size_t i_end = i, j_end = j;
      while (i_end < a.size() && std::isdigit(static_cast<unsigned char>(a[i_end]))) ++i_end;
      while (j_end < b.size() && std::isdigit(static_cast<unsigned char>(b[j_end]))) ++j_end;
      std::string x = a.substr(i, i_end - i), y = b.substr(j, j_end - j);
      x.erase(0, std::min(x.find_first_not_of('0'), x.size()));
      y.erase(0, std::min(y.find_first_not_of('0'), y.size()));
      if (x.size() != y.size()) return x.size() < y.size();
      if (x != y) return x < y;
      i = i_end;
      j = j_end;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i;
      ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

}  // namespace

std::vector<fs::path> list_mesh_frames(const fs::path& folder) {
  std::error_code error;
  if (!fs::is_directory(folder, error))
    throw IoError(ErrorKind::file_unreadable, folder.string() + ": not a folder of base frames");
  std::vector<fs::path> frames;
  for (const auto& entry : fs::directory_iterator(folder)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (entry.is_regular_file() && (ext == ".obj" || ext == ".ply" || ext == ".off" || ext == ".stl"))
      frames.push_back(entry.path());
  }
  if (frames.empty())
    throw InputError(folder.string() + ": no base frames (.obj .ply .off .stl) in it",
                     ErrorKind::invalid_option);
  std::sort(frames.begin(), frames.end(), [](const fs::path& a, const fs::path& b) {
    return natural_less(a.filename().string(), b.filename().string());
  });
  return frames;
}

BaseFrames::BaseFrames(std::vector<fs::path> files, const QuiltTexture& texture)
    : files_(std::move(files)), reference_(read_mesh(files_[0])) {
  prepared_ = prepare_base(reference_, files_[0].string());
  check_texture_base(texture, prepared_, files_[0].string());
  sources_ = prepared_vertex_sources(reference_);
}

TriMesh BaseFrames::posed(size_t k) const {
  const TriMesh frame = k == 0 ? reference_ : read_mesh(files_[k]);
  if (frame.num_vertices() != reference_.num_vertices() || frame.triangles != reference_.triangles)
    throw InputError(files_[k].string() + ": " + std::to_string(frame.num_vertices()) + " vertices and " +
                         std::to_string(frame.num_faces()) + " faces, not the first frame's " +
                         std::to_string(reference_.num_vertices()) + " and " +
                         std::to_string(reference_.num_faces()) + " in the same order",
                     ErrorKind::base_mismatch);
  return posed_base(prepared_, sources_, frame);
}

namespace {

double largest_move(const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
  double largest = 0.0;
  for (size_t v = 0; v < from.size(); ++v) largest = std::max(largest, glm::length(to[v] - from[v]));
  return largest;
}

}  // namespace

void run_embed_frames(const EmbedFramesArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  check_mesh_output("frame." + args.format);
  const std::vector<fs::path> files = list_mesh_frames(args.frames);
  std::error_code error;
  fs::create_directories(args.output, error);
  check_writable(fs::path(args.output) / "frame");
  if (!args.stats.empty()) check_writable(args.stats);
  const QuiltTexture texture = read_texture_file(args.texture);

  // A record of what made the frames already in the folder: kept only when it matches.
  const nlohmann::json made_by = {{"texture_sha256", sha256_file(args.texture)},
                                  {"embed", args.embed},
                                  {"format", args.format},
                                  {"provenance", args.provenance}};
  const fs::path record = fs::path(args.output) / ".meshquilt-frames.json";
  bool resume = false;
  if (fs::exists(record)) {
    try {
      std::ifstream in(record);
      resume = nlohmann::json::parse(in) == made_by;
    } catch (const std::exception&) {
      resume = false;
    }
  }
  write_text_atomic(record, made_by.dump(2) + "\n");

  const BaseFrames frames(files, texture);

  nlohmann::json per_frame = nlohmann::json::array();
  std::vector<Vec3> previous_output, previous_base;
  double largest_jump = 0.0, largest_base_motion = 0.0, slowest = 0.0;
  int made = 0, kept = 0;
  for (size_t k = 0; k < frames.size(); ++k) {
    const auto frame_start = std::chrono::steady_clock::now();
    const std::string name = frames.file(k).string();
    const TriMesh posed = frames.posed(k);
    const fs::path out = fs::path(args.output) / (frames.file(k).stem().string() + "." + args.format);
    nlohmann::json entry = {{"base", name}, {"output", out.string()}};
    if (resume && fs::exists(out)) {
      ++kept;
      entry["kept"] = true;
      previous_output.clear();
    } else {
      PlacedTexture placed = place_texture(texture, posed, args.embed, args.texture);
      if (!args.provenance) placed.mesh.origins.clear();
      write_mesh(placed.mesh, out);
      ++made;
      if (!previous_output.empty()) {
        const double jump = largest_move(previous_output, placed.mesh.positions);
        const double motion = largest_move(previous_base, posed.positions);
        entry["largest_jump"] = jump;
        entry["largest_base_motion"] = motion;
        largest_jump = std::max(largest_jump, jump);
        largest_base_motion = std::max(largest_base_motion, motion);
      }
      previous_output = placed.mesh.positions;
    }
    previous_base = posed.positions;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - frame_start).count();
    slowest = std::max(slowest, seconds);
    entry["seconds"] = seconds;
    per_frame.push_back(entry);
    std::printf("frame %zu/%zu %s: %s in %.2f s\n", k + 1, frames.size(), out.filename().string().c_str(),
                entry.contains("kept") ? "kept" : "written", seconds);
    std::fflush(stdout);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const nlohmann::json summary = {{"texture", args.texture},
                                  {"frames", frames.size()},
                                  {"made", made},
                                  {"kept", kept},
                                  {"largest_jump", largest_jump},
                                  {"largest_base_motion", largest_base_motion},
                                  {"slowest_frame_seconds", slowest},
                                  {"seconds", seconds},
                                  {"per_frame", per_frame}};
  if (!args.stats.empty()) write_text_atomic(args.stats, summary.dump(2) + "\n");
  std::printf("wrote %d frames to %s (%d kept) in %.2f s; largest vertex jump %.6g, base motion %.6g\n", made,
              args.output.c_str(), kept, seconds, largest_jump, largest_base_motion);
}

}  // namespace meshquilt::cli
