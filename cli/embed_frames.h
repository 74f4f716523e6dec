#pragma once
// `meshquilt embed --texture T.mqt --base-frames DIR -o FRAMES/`: one synthesized layer over
// every frame of an animated base with the same connectivity.

#include <filesystem>
#include <string>
#include <vector>

#include "mesh/tri_mesh.h"
#include "shell/texture_file.h"

namespace meshquilt::cli {

struct EmbedFramesArgs {
  std::string texture;
  std::string frames;  // folder of base frames
  std::string output;  // folder for the output frames
  std::string embed = "auto";
  std::string format = "ply";
  std::string stats;
  bool provenance = false;
};

// Frames are the folder's .obj .ply .off .stl files in natural order (frame2 before frame10).
// The first frame is prepared as `embed --base` does; every later one must have its raw vertex
// count and faces and is posed on that preparation by raw vertex index, never welded again.
// Each output frame is written as it finishes (atomically); a rerun with the same texture and
// options keeps the frames already there and makes only the missing ones.
// \throw IoError(file_unreadable) for a missing folder; InputError(invalid_option) for a folder
//        without frames; InputError(base_mismatch) "FRAME: problem" for a frame of another
//        connectivity (earlier frames stay written).
void run_embed_frames(const EmbedFramesArgs& args);

// The frames of an animated base, posed on the first one's preparation by raw vertex index (never
// welded again), checked against a texture.
class BaseFrames {
 public:
  // \throw as read_mesh and prepare_base; InputError(base_mismatch) when the first frame is not
  //        the texture's base up to positions.
  BaseFrames(std::vector<std::filesystem::path> files, const QuiltTexture& texture);
  size_t size() const { return files_.size(); }
  const std::filesystem::path& file(size_t k) const { return files_[k]; }
  // Frame k prepared. \throw InputError(base_mismatch) naming it when its raw vertices and faces
  //        are not the first frame's.
  TriMesh posed(size_t k) const;

 private:
  std::vector<std::filesystem::path> files_;
  TriMesh reference_, prepared_;
  std::vector<int32_t> sources_;
};

// The .obj .ply .off .stl files of a folder in natural order.
// \throw IoError(file_unreadable) for a missing folder; InputError(invalid_option) for none.
std::vector<std::filesystem::path> list_mesh_frames(const std::filesystem::path& folder);

}  // namespace meshquilt::cli
