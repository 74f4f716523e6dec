#pragma once
//! Where the CLI keeps what it can reuse between jobs (the matcher's nearest-face grids).

#include <filesystem>

namespace meshquilt::cli {

//! $MESHQUILT_CACHE when set ("off" or empty: nothing is kept), else $XDG_CACHE_HOME/meshquilt,
//! else $HOME/.cache/meshquilt; empty when none of them is set.
std::filesystem::path cache_folder();

}  // namespace meshquilt::cli
