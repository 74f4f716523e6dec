#pragma once
//! A texture-space layer (`synth --write-texture`) placed over a base with its connectivity: what
//! `embed`, `edit`, `animate`, `embed --base-frames` and the Python module share.

#include <string>

#include "mesh/tri_mesh.h"
#include "shell/texture_file.h"

namespace meshquilt {

struct PlacedTexture {
  TriMesh mesh;            //!< positions, triangles, elements, sources and origins
  bool shell_map = false;  //!< placed through the shell map (else normal displacement)
  int shell_reduced_vertices = 0;
  int synthesis_map_elements = 0;
};

//! `embed`: auto (as synth embedded it), shell or normal. `base` is prepared (prepare_base) and
//! checked against the texture. \throw InputError(invalid_option) for another mode, or shell for a
//! texture written with --embed normal (`texture_name` names it).
PlacedTexture place_texture(const QuiltTexture& texture, const TriMesh& base, const std::string& embed,
                            const std::string& texture_name);

}  // namespace meshquilt
