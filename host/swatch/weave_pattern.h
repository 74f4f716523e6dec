#pragma once
//! Weave patterns (paper 004, Section 3): which yarn lies on top at each warp/weft crossing.

#include <cstdint>
#include <string>
#include <vector>

#include "swatch/netpbm.h"

namespace meshquilt {

//! One repeat of a weave. Warps are the columns (ends), wefts the rows (picks).
//! warp_over  #wefts x #warps, row-major: 1 where warp i passes over weft j
struct WeavePattern {
  int warps = 0;
  int wefts = 0;
  std::vector<uint8_t> warp_over;

  //! Whether warp i is above weft j; indices wrap around the repeat (negative ones too).
  bool over(int warp, int weft) const {
    const int i = ((warp % warps) + warps) % warps;
    const int j = ((weft % wefts) + wefts) % wefts;
    return warp_over[static_cast<size_t>(j) * warps + i] != 0;
  }
};

//! M/N twill of M+N ends: warp i is over weft j when (i - j) mod (M+N) < M (each row shifted by
//! one). twill_pattern(1, 1) is the plain weave.
//! \throw InputError(invalid_option) unless 1 <= M, N and M+N <= 64.
WeavePattern twill_pattern(int over, int under);

//! The step of a regular satin of `ends` ends: the smallest s with 1 < s < ends-1 and
//! gcd(s, ends) = 1, or 0 when there is none (ends 3, 4 and 6, for example).
int satin_step(int ends);

//! M/N regular satin: warp i is over weft j when (i - s j) mod (M+N) < M with s = satin_step(M+N),
//! so interlacings of neighbouring rows are never adjacent.
//! \throw InputError(invalid_option) when M or N < 1, M+N > 64, or M+N has no satin step
//!        (e.g. satin 3/1).
WeavePattern satin_pattern(int over, int under);

//! A Jacquard design from an image: one warp per column, one weft per row; a dark pixel
//! (intensity < 0.5) puts the warp over the weft. Weft j is image row height-1-j, so the design
//! reads upright seen from +z with wefts stacked along +y.
//! \throw InputError(invalid_option) when the image has more than 1024 columns or rows.
WeavePattern image_pattern(const GrayImage& image);

//! Parses "plain", "twill:M/N", "satin:M/N", or the path of a PBM/PGM/PPM image (Jacquard).
//! \throw InputError(invalid_option) for a malformed or invalid pattern; IoError from
//!        read_netpbm for an image that cannot be read.
WeavePattern parse_weave_pattern(const std::string& spec);

}  // namespace meshquilt
