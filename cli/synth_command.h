#pragma once
//! `meshquilt synth`: one quilting job from parsed options.

#include "synth_options.h"

namespace meshquilt::cli {

//! Runs the job `args` describes: reads the swatch, quilts the plane, writes the output mesh
//! (and stats JSON) atomically and prints one summary line (or JSON lines with --progress json).
//! Polls interrupt_token(). \throw meshquilt::Error (InputError, IoError, DeviceError, ...).
void run_synth(const SynthArgs& args);

}  // namespace meshquilt::cli
