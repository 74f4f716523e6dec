#pragma once
// `meshquilt embed --texture T.mqt --base-frames DIR -o FRAMES/`: one synthesized layer over
// every frame of an animated base with the same connectivity.

#include <filesystem>
#include <string>
#include <vector>

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

// The .obj .ply .off .stl files of a folder in natural order.
// \throw IoError(file_unreadable) for a missing folder; InputError(invalid_option) for none.
std::vector<std::filesystem::path> list_mesh_frames(const std::filesystem::path& folder);

}  // namespace meshquilt::cli
