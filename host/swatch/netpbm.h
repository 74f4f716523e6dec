#pragma once
//! A reader for the Netpbm image formats (PBM P1/P4, PGM P2/P5, PPM P3/P6), written here so
//! height fields and Jacquard weave designs need no image library.

#include <filesystem>
#include <string>
#include <vector>

namespace meshquilt {

//! A grayscale image with intensities in [0, 1] (0 black, 1 white).
//! values  #height x #width, row-major, row 0 the top row of the image as viewed
struct GrayImage {
  int width = 0;
  int height = 0;
  std::vector<double> values;
  //! A PPM's own colours: #(width x height x 3), R G B per pixel in [0, 1]; empty for PBM and PGM.
  std::vector<double> rgb;

  double at(int column, int row) const { return values[static_cast<size_t>(row) * width + column]; }
};

//! Reads a PBM (1 = black), PGM (maxval 1..65535) or PPM (converted to luma, Rec. 601 weights)
//! file in plain or raw form; '#' comments in the header are skipped.
//! \throw IoError(file_unreadable) when the file is missing, unreadable, truncated or corrupt;
//!        IoError(unknown_format) when it does not start with a Netpbm magic number P1..P6.
//!        Messages read "FILE: problem".
GrayImage read_netpbm(const std::filesystem::path& file);

//! Parses Netpbm bytes already in memory (`name` prefixes messages); read_netpbm calls it, and
//! so does the fuzz target. Same errors as read_netpbm, plus IoError(file_unreadable) "header
//! declares W x H pixels, more than the N bytes after it hold" before any pixel is allocated.
GrayImage parse_netpbm(std::string bytes, const std::string& name);

}  // namespace meshquilt
