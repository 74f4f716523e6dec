#include "swatch/default_swatch.h"

#include "swatch/chainmail.h"

namespace meshquilt {

TriMesh default_swatch() {
  ChainmailOptions options;
  options.rows = 4;
  options.columns = 4;
  options.ring_segments = 16;
  options.wire_segments = 6;
  return make_chainmail(options);
}

}  // namespace meshquilt
