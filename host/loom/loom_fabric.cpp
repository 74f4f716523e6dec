#include "loom/loom_fabric.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "core/atomic_write.h"
#include <glm/geometric.hpp>

#include "core/constants.h"

namespace meshquilt {
namespace {

// One station of a yarn: sideways offset, height and the cross-section's radii.
struct Station {
  double side = 0.0, z = 0.0;
  std::vector<double> radius;
};

Station station_of(const YarnProfile& p, size_t s, int sides, double scale, double mid_z) {
  Station out{p.centre[s].x * scale, (p.centre[s].y - mid_z) * scale, {}};
  for (int k = 0; k < sides; ++k) out.radius.push_back(p.radius[s * sides + k] * scale);
  return out;
}

Station lerp(const Station& a, const Station& b, double w) {
  Station out{(1.0 - w) * a.side + w * b.side, (1.0 - w) * a.z + w * b.z, {}};
  for (size_t k = 0; k < a.radius.size(); ++k) out.radius.push_back((1.0 - w) * a.radius[k] + w * b.radius[k]);
  return out;
}

Station difference(const Station& a, const Station& b) {  // a - b
  Station out{a.side - b.side, a.z - b.z, {}};
  for (size_t k = 0; k < a.radius.size(); ++k) out.radius.push_back(a.radius[k] - b.radius[k]);
  return out;
}

void add(Station& a, const Station& d, double w) {
  a.side += w * d.side;
  a.z += w * d.z;
  for (size_t k = 0; k < a.radius.size(); ++k) a.radius[k] += w * d.radius[k];
}

// Blocks' pieces of one yarn, in order along it, each per_pitch + 1 stations; seams closed at the
// mean of the two ends, each piece moved linearly between its two ends' corrections; joined. When
// `periodic`, the yarn's two ends are one more seam.
std::vector<Station> join_pieces(std::vector<std::vector<Station>>& pieces, bool periodic) {
  const size_t n = pieces.size();
  std::vector<Station> seam(n + 1);  // correction targets: seam k lies between piece k - 1 and k
  for (size_t k = 1; k < n; ++k) seam[k] = lerp(pieces[k - 1].back(), pieces[k].front(), 0.5);
  if (periodic) seam[0] = seam[n] = lerp(pieces[n - 1].back(), pieces[0].front(), 0.5);
  std::vector<Station> yarn;
  for (size_t k = 0; k < n; ++k) {
    std::vector<Station>& piece = pieces[k];
    const size_t last = piece.size() - 1;
    const Station zero = difference(piece.front(), piece.front());
    const Station top = k > 0 || periodic ? difference(seam[k], piece.front()) : zero;
    const Station bottom = k + 1 < n || periodic ? difference(seam[k + 1], piece.back()) : zero;
    for (size_t j = k > 0 ? 1 : 0; j <= last; ++j) {
      const double w = static_cast<double>(j) / static_cast<double>(last);
      Station s = piece[j];
      add(s, top, 1.0 - w);
      add(s, bottom, w);
      yarn.push_back(std::move(s));
    }
  }
  return yarn;
}

// A yarn's tube: station s at run position start + s run_step along `run`, its centre offset
// sideways along `side` and up, its radii turning from `side` toward +z; then the centres of
// its two caps. Rings of `sides` vertices, station by station.
std::vector<Vec3> tube_positions(const std::vector<Station>& yarn, int sides, const glm::dvec3& run,
                                 const glm::dvec3& side, const glm::dvec3& start, double run_step) {
  const glm::dvec3 up(0.0, 0.0, 1.0);
  std::vector<Vec3> positions;
  positions.reserve(yarn.size() * static_cast<size_t>(sides) + 2);
  for (size_t s = 0; s < yarn.size(); ++s) {
    const glm::dvec3 c = start + run * (run_step * static_cast<double>(s)) + side * yarn[s].side + up * yarn[s].z;
    for (int k = 0; k < sides; ++k) {
      const double a = 2.0 * kPi * k / sides;
      positions.push_back(c + yarn[s].radius[k] * (std::cos(a) * side + std::sin(a) * up));
    }
  }
  for (const size_t s : {size_t{0}, yarn.size() - 1})
    positions.push_back(start + run * (run_step * static_cast<double>(s)) + side * yarn[s].side + up * yarn[s].z);
  return positions;
}

// The tube's faces over its own vertices (see tube_positions), wound one way or the other.
std::vector<Tri> tube_triangles(size_t stations, int sides, bool flip) {
  const auto at = [sides](size_t s, int k) { return static_cast<int32_t>(s * sides + (k % sides)); };
  std::vector<Tri> t;
  t.reserve(2 * static_cast<size_t>(sides) * stations);
  for (size_t s = 0; s + 1 < stations; ++s)
    for (int k = 0; k < sides; ++k) {
      t.push_back({at(s, k), at(s + 1, k), at(s + 1, k + 1)});
      t.push_back({at(s, k), at(s + 1, k + 1), at(s, k + 1)});
    }
  const int32_t head = static_cast<int32_t>(stations * sides), tail = head + 1;
  for (int k = 0; k < sides; ++k) {
    t.push_back({head, at(0, k), at(0, k + 1)});
    t.push_back({tail, at(stations - 1, k + 1), at(stations - 1, k)});
  }
  if (flip)
    for (Tri& f : t) std::swap(f[1], f[2]);
  return t;
}

// Whether a tube (tube_positions' layout) must be wound the other way to face outward: its
// enclosed volume is negative as tube_triangles winds it.
bool inward(const std::vector<Vec3>& positions, int sides) {
  double volume = 0.0;
  for (const Tri& t : tube_triangles((positions.size() - 2) / static_cast<size_t>(sides), sides, false))
    volume += glm::dot(positions[t[0]], glm::cross(positions[t[1]], positions[t[2]]));
  return volume < 0.0;
}

// A tube appended to `mesh` as element `element`, wound outward, in `colour` when given.
void append_tube(TriMesh& mesh, const std::vector<Vec3>& positions, int sides, const std::array<uint8_t, 3>* colour,
                 int32_t element) {
  const size_t stations = (positions.size() - 2) / static_cast<size_t>(sides);
  const int32_t first = static_cast<int32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), positions.begin(), positions.end());
  if (colour) mesh.colors.resize(mesh.positions.size(), *colour);
  for (const Tri& t : tube_triangles(stations, sides, inward(positions, sides)))
    mesh.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
  mesh.elements.resize(mesh.triangles.size(), element);
}

// Where blocks from different exemplars, or inconsistent ones, meet, the two yarns of a crossing
// may come closer than their radii allow. Over the stations of each yarn that pass over (or
// under) the other's cross-section, the shortfall in height is measured against that section's
// height at that distance from its centre; the upper yarn is raised and the lower one lowered by
// half of it each, over a raised-cosine bump a pitch to either side, until none is short.
void separate_crossings(std::vector<std::vector<Station>>& warps, std::vector<std::vector<Station>>& wefts, int pp,
                        int sides, double warp_step, double weft_step, bool periodic) {
  const int rows = static_cast<int>(wefts.size()), columns = static_cast<int>(warps.size());
  const size_t up_k = static_cast<size_t>(sides / 4), down_k = static_cast<size_t>(3 * sides / 4);
  // A repeating yarn's first and last stations are one: a bump wraps round and moves both.
  const auto bump = [&](std::vector<Station>& yarn, int centre, double lift) {
    const int period = static_cast<int>(yarn.size()) - 1;
    for (int d = -pp; d <= pp; ++d) {
      const double dz = lift * 0.5 * (1.0 + std::cos(kPi * d / pp));
      int s = centre + d;
      if (periodic) {
        s = ((s % period) + period) % period;
        yarn[s].z += dz;
        if (s == 0) yarn[period].z += dz;
      } else if (s >= 0 && s <= period) {
        yarn[s].z += dz;
      }
    }
  };
  // Over the plan of a crossing, station by station of both yarns: how far the upper one's
  // underside falls short of clearing the lower one's top, with a tenth of their radii spare. A
  // section's height at a sideways distance from its centre is that of an ellipse through its
  // side and its top (or bottom) radii.
  const auto height = [](double vertical, double sideways, double off) {
    const double t = std::abs(off) / sideways;
    return t < 1.0 ? vertical * std::sqrt(1.0 - t * t) : -1.0;
  };
  // What the test needs of a station, sampled at a quarter of the station spacing with stations
  // interpolated linearly.
  struct Section {
    double z, side, up, down, half_width;
  };
  const auto at = [&](const std::vector<Station>& yarn, int centre, int quarter) {
    const int whole = quarter >= 0 ? quarter / 4 : -((-quarter + 3) / 4);
    const double w = (quarter - 4 * whole) / 4.0;
    const Station& a = yarn[static_cast<size_t>(centre + whole)];
    const Station& b = w > 0.0 ? yarn[static_cast<size_t>(centre + whole + 1)] : a;
    const auto mix = [w](double x, double y) { return (1.0 - w) * x + w * y; };
    const size_t left = static_cast<size_t>(sides / 2);
    return Section{mix(a.z, b.z), mix(a.side, b.side), mix(a.radius[up_k], b.radius[up_k]),
                   mix(a.radius[down_k], b.radius[down_k]),
                   std::max(mix(a.radius[0], b.radius[0]), mix(a.radius[left], b.radius[left]))};
  };
  const auto shortfall = [&](const std::vector<Station>& warp, int sw, const std::vector<Station>& weft, int sf,
                             bool warp_up) {
    double worst = 0.0;
    for (int qw = -2 * pp; qw <= 2 * pp; ++qw) {
      const Section w = at(warp, sw, qw);
      for (int qf = -2 * pp; qf <= 2 * pp; ++qf) {
        const Section f = at(weft, sf, qf);
        // The plan point under both samples, off each centre sideways: the warp runs down (-y)
        // from its nominal x, the weft along +x from its nominal y.
        const double off_w = 0.25 * qf * weft_step - w.side, off_f = -0.25 * qw * warp_step - f.side;
        const Section& up = warp_up ? w : f;
        const Section& down = warp_up ? f : w;
        const double under = height(up.down, up.half_width, warp_up ? off_w : off_f);
        const double over = height(down.up, down.half_width, warp_up ? off_f : off_w);
        if (under < 0.0 || over < 0.0) continue;
        worst = std::max(worst, (down.z + over + 0.1 * (up.down + down.up)) - (up.z - under));
      }
    }
    return worst;
  };
  // Every crossing once, then those near a crossing that moved, until none is short.
  std::vector<uint8_t> due(static_cast<size_t>(rows) * columns, 1);
  for (int pass = 0; pass < 16; ++pass) {
    std::vector<uint8_t> next(due.size(), 0);
    bool moved = false;
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < columns; ++c) {
        if (!due[static_cast<size_t>(r) * columns + c]) continue;
        const int sw = r * pp + pp / 2, sf = c * pp + pp / 2;
        const bool warp_up = warps[c][static_cast<size_t>(sw)].z >= wefts[r][static_cast<size_t>(sf)].z;
        const double short_by = shortfall(warps[c], sw, wefts[r], sf, warp_up);
        if (short_by <= 1e-12) continue;
        moved = true;
        bump(warps[c], sw, warp_up ? 0.5 * short_by : -0.5 * short_by);
        bump(wefts[r], sf, warp_up ? -0.5 * short_by : 0.5 * short_by);
        for (int dr = -2; dr <= 2; ++dr)
          for (int dc = -2; dc <= 2; ++dc)
            if (r + dr >= 0 && r + dr < rows && c + dc >= 0 && c + dc < columns)
              next[static_cast<size_t>(r + dr) * columns + c + dc] = 1;
      }
    if (!moved) break;
    due.swap(next);
  }
}

// The design's yarns, station by station, ready to sweep.
struct WovenYarns {
  LoomGrid grid;
  glm::dvec2 pitch{0.0};
  int per_pitch = 0, sides = 0;
  std::vector<std::vector<Station>> warps, wefts;

  size_t count() const { return warps.size() + wefts.size(); }
  // Yarn i: warps first (element c), then wefts (element columns + r).
  const std::vector<Station>& yarn(size_t i) const { return i < warps.size() ? warps[i] : wefts[i - warps.size()]; }
  std::vector<Vec3> positions(size_t i) const {
    if (i < warps.size()) {
      const glm::dvec2 top = grid.origin + static_cast<double>(i) * grid.column_step - 0.5 * grid.row_step;
      return tube_positions(warps[i], sides, glm::dvec3(0.0, -1.0, 0.0), glm::dvec3(1.0, 0.0, 0.0),
                            glm::dvec3(top, 0.0), pitch.y / per_pitch);
    }
    const size_t r = i - warps.size();
    const glm::dvec2 left = grid.origin + static_cast<double>(r) * grid.row_step - 0.5 * grid.column_step;
    return tube_positions(wefts[r], sides, glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 1.0, 0.0),
                          glm::dvec3(left, 0.0), pitch.x / per_pitch);
  }
};

WovenYarns weave_yarns(const LoomDesign& design, const LoomAssignment& assignment,
                       const std::vector<ExemplarProfiles>& exemplars, bool periodic) {
  WovenYarns out;
  const glm::dvec2 pitch = exemplars[0].weave.pitch;
  const int pp = exemplars[0].per_pitch, sides = exemplars[0].sides;
  out.pitch = pitch;
  out.per_pitch = pp;
  out.sides = sides;
  LoomGrid& grid = out.grid;
  grid.rows = design.rows;
  grid.columns = design.columns;
  grid.origin = glm::dvec2(0.5 * pitch.x, (design.rows - 0.5) * pitch.y);
  grid.row_step = glm::dvec2(0.0, -pitch.y);
  grid.column_step = glm::dvec2(pitch.x, 0.0);
  std::vector<double> scale, mid_z;
  for (const ExemplarProfiles& e : exemplars) {
    scale.push_back(0.5 * (pitch.x / e.weave.pitch.x + pitch.y / e.weave.pitch.y));
    double sum = 0.0, count = 0.0;
    for (const auto* yarns : {&e.warps, &e.wefts})
      for (const YarnProfile& y : *yarns)
        for (const glm::dvec2& c : y.centre) {
          sum += c.y;
          count += 1.0;
        }
    mid_z.push_back(count > 0.0 ? sum / count : 0.0);
  }
  // Warp c runs down the design (row r + 1 is the exemplar's weft y - 1): stations from the
  // block's top, (y + 1) per_pitch, down to y per_pitch.
  for (int c = 0; c < design.columns; ++c) {
    std::vector<std::vector<Station>> pieces;
    for (int r = 0; r < design.rows; ++r) {
      const LoomBlock& b = assignment.at(r, c);
      const YarnProfile& p = exemplars[b.exemplar].warps[b.x];
      std::vector<Station>& piece = pieces.emplace_back();
      for (int j = 0; j <= pp; ++j)
        piece.push_back(station_of(p, static_cast<size_t>((b.y + 1) * pp - j), sides, scale[b.exemplar], mid_z[b.exemplar]));
    }
    out.warps.push_back(join_pieces(pieces, periodic));
  }
  // Weft r runs across the design with the exemplar's x: stations x per_pitch to (x + 1) per_pitch.
  for (int r = 0; r < design.rows; ++r) {
    std::vector<std::vector<Station>> pieces;
    for (int c = 0; c < design.columns; ++c) {
      const LoomBlock& b = assignment.at(r, c);
      const YarnProfile& p = exemplars[b.exemplar].wefts[b.y];
      std::vector<Station>& piece = pieces.emplace_back();
      for (int j = 0; j <= pp; ++j)
        piece.push_back(station_of(p, static_cast<size_t>(b.x * pp + j), sides, scale[b.exemplar], mid_z[b.exemplar]));
    }
    out.wefts.push_back(join_pieces(pieces, periodic));
  }
  separate_crossings(out.warps, out.wefts, pp, sides, pitch.y / pp, pitch.x / pp, periodic);
  return out;
}

}  // namespace

LoomFabric weave_fabric(const LoomDesign& design, const LoomAssignment& assignment,
                        const std::vector<ExemplarProfiles>& exemplars, const YarnColours& colours,
                        bool periodic) {
  const WovenYarns yarns = weave_yarns(design, assignment, exemplars, periodic);
  LoomFabric out;
  out.grid = yarns.grid;
  TriMesh& mesh = out.mesh;
  for (size_t i = 0; i < yarns.count(); ++i) {
    append_tube(mesh, yarns.positions(i), yarns.sides, colours.empty() ? nullptr : &colours[i],
                static_cast<int32_t>(i));
  }
  return out;
}

LoomFabric drape_fabric(const LoomDesign& design, const LoomAssignment& assignment,
                        const std::vector<ExemplarProfiles>& exemplars, const FabricPlacement& place,
                        const YarnColours& colours, bool periodic) {
  const WovenYarns yarns = weave_yarns(design, assignment, exemplars, periodic);
  LoomFabric out;
  out.grid = yarns.grid;
  std::vector<std::vector<Vec3>> flat(yarns.count());
  double underside = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < yarns.count(); ++i) {
    flat[i] = yarns.positions(i);
    for (const Vec3& p : flat[i]) underside = std::min(underside, p.z);
  }
  TriMesh& mesh = out.mesh;
  const size_t sides = static_cast<size_t>(yarns.sides);
  int32_t element = 0;
  for (size_t i = 0; i < yarns.count(); ++i) {
    // Each station whose whole ring lands on the base; runs of two or more become tubes.
    const size_t stations = yarns.yarn(i).size();
    std::vector<Vec3> placed(stations * sides);
    std::vector<uint8_t> landed(stations, 1);
    for (size_t s = 0; s < stations; ++s)
      for (size_t k = 0; k < sides && landed[s]; ++k) {
        const Vec3& p = flat[i][s * sides + k];
        const std::optional<Vec3> q = place(Vec3(p.x, p.y, p.z - underside));
        if (q)
          placed[s * sides + k] = *q;
        else
          landed[s] = 0;
      }
    for (size_t s = 0; s < stations;) {
      size_t end = s;
      while (end < stations && landed[end]) ++end;
      if (end - s >= 2) {
        std::vector<Vec3> positions(placed.begin() + static_cast<std::ptrdiff_t>(s * sides),
                                    placed.begin() + static_cast<std::ptrdiff_t>(end * sides));
        for (const size_t ring : {s, end - 1}) {  // cap centres: the mean of their rings
          Vec3 centre(0.0);
          for (size_t k = 0; k < sides; ++k) centre += placed[ring * sides + k] / static_cast<double>(sides);
          positions.push_back(centre);
        }
        append_tube(mesh, positions, yarns.sides, colours.empty() ? nullptr : &colours[i], element++);
      }
      s = std::max(end, s + 1);
    }
  }
  return out;
}

LoomFabricFile write_fabric_ply(const LoomDesign& design, const LoomAssignment& assignment,
                                const std::vector<ExemplarProfiles>& exemplars, const std::filesystem::path& file,
                                const YarnColours& colours, bool periodic, const CancelToken* cancel) {
  const WovenYarns yarns = weave_yarns(design, assignment, exemplars, periodic);
  LoomFabricFile out;
  out.grid = yarns.grid;
  const size_t sides = static_cast<size_t>(yarns.sides);
  for (size_t i = 0; i < yarns.count(); ++i) {
    out.vertices += yarns.yarn(i).size() * sides + 2;
    out.faces += 2 * sides * yarns.yarn(i).size();
  }
  AtomicFileStream stream(file, cancel);
  stream.write("ply\nformat binary_little_endian 1.0\ncomment written by meshquilt\nelement vertex " +
               std::to_string(out.vertices) + "\nproperty double x\nproperty double y\nproperty double z\n" +
               (colours.empty() ? "" : "property uchar red\nproperty uchar green\nproperty uchar blue\n") + "element face " +
               std::to_string(out.faces) + "\nproperty list uchar int vertex_indices\nproperty int element\nend_header\n");
  // Vertices yarn by yarn, noting which tubes turn inward; then the faces, which need no positions.
  std::vector<uint8_t> flip(yarns.count(), 0);
  std::string bytes;
  for (size_t i = 0; i < yarns.count(); ++i) {
    const std::vector<Vec3> positions = yarns.positions(i);
    flip[i] = inward(positions, yarns.sides) ? 1 : 0;
    if (colours.empty()) {
      bytes.resize(positions.size() * 3 * sizeof(double));
      std::memcpy(bytes.data(), positions.data(), bytes.size());
    } else {
      const size_t stride = 3 * sizeof(double) + 3;
      bytes.resize(positions.size() * stride);
      for (size_t v = 0; v < positions.size(); ++v) {
        std::memcpy(bytes.data() + v * stride, &positions[v], 3 * sizeof(double));
        std::memcpy(bytes.data() + v * stride + 3 * sizeof(double), colours[i].data(), 3);
      }
    }
    stream.write(bytes);
  }
  int64_t first = 0;
  for (size_t i = 0; i < yarns.count(); ++i) {
    const std::vector<Tri> triangles = tube_triangles(yarns.yarn(i).size(), yarns.sides, flip[i] != 0);
    bytes.resize(triangles.size() * 17);
    char* at = bytes.data();
    const int32_t element = static_cast<int32_t>(i);
    for (const Tri& t : triangles) {
      *at++ = 3;
      for (int k = 0; k < 3; ++k) {
        const int32_t v = static_cast<int32_t>(t[k] + first);
        std::memcpy(at, &v, 4);
        at += 4;
      }
      std::memcpy(at, &element, 4);
      at += 4;
    }
    stream.write(bytes);
    first += static_cast<int64_t>(yarns.yarn(i).size() * sides + 2);
  }
  stream.commit();
  return out;
}

}  // namespace meshquilt
