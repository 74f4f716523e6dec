#pragma once
//! The rules the patch step applies between the paper's stages, each by name: which related
//! elements are merge partners, and when a deformed or merged element may not be kept because it
//! would pass through a neighbour.

#include <cstdint>
#include <vector>

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

//! Collision policy: true when a face of `candidate` intersects a face of one of `others` (exact
//! triangle-triangle tests). A deformation that does so is undone; a merge or an input that does
//! so is refused.
bool passes_through(const TriMesh& candidate, const std::vector<const TriMesh*>& others);

}  // namespace meshquilt
