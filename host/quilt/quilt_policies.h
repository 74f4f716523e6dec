#pragma once
//! The rules the patch step applies between the paper's stages, each by name: which related
//! elements are merge partners, and when a deformed or merged element may not be kept because it
//! would pass through a neighbour.

#include <cstdint>
#include <vector>

#include "mesh/measures.h"
#include "mesh/tri_mesh.h"
#include "quilt/correspondence.h"

namespace meshquilt {

//! Merge partners, one to one, in decreasing order of shared pairs (the order of
//! `correspondences.relations`). A relation whose pairs lie on average farther apart than
//! `max_mean_distance` is a neighbour seen through a misregistered seam, not a twin: deforming or
//! merging it would bend both out of shape, so it is no partner. Interlinked elements (chain mail)
//! relate to their linked neighbours through a few pairs where the rings pass through each other;
//! taking partners one to one keeps those out.
//! in_partnered  #inputs, set to 1 for every input that got a partner
std::vector<const ElementRelation*> choose_partners(const Correspondences& correspondences, size_t outputs,
                                                    size_t inputs, double max_mean_distance,
                                                    std::vector<uint8_t>& in_partnered);

//! The bounding boxes of a mesh's faces in runs of kFaceRun consecutive faces (the last run
//! shorter). A generated element's faces come in sweep order, so a run is compact, and a search
//! for the faces that meet a box passes over every run whose box misses it.
inline constexpr size_t kFaceRun = 16;
std::vector<Box3> face_run_boxes(const TriMesh& mesh);

//! A mesh as passes_through searches it: the mesh and its face_run_boxes (both outlive the call).
struct CollisionMesh {
  const TriMesh* mesh;
  const std::vector<Box3>* runs;
};

//! Collision policy: true when a face of `candidate` intersects a face of one of `others` (exact
//! triangle-triangle tests). A deformation that does so is undone; a merge or an input that does
//! so is refused. Callers that test many candidates against the same neighbours keep their
//! runs; the answer does not depend on them.
bool passes_through(const TriMesh& candidate, const std::vector<CollisionMesh>& others);
//! The same, with the others' runs measured for this call.
bool passes_through(const TriMesh& candidate, const std::vector<const TriMesh*>& others);

}  // namespace meshquilt
