#include "loom/loom_fabric.h"

#include <cmath>
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
// mean of the two ends, each piece moved linearly between its two ends' corrections; joined.
std::vector<Station> join_pieces(std::vector<std::vector<Station>>& pieces) {
  const size_t n = pieces.size();
  std::vector<Station> seam(n + 1);  // correction targets: seam k lies between piece k - 1 and k
  for (size_t k = 1; k < n; ++k) seam[k] = lerp(pieces[k - 1].back(), pieces[k].front(), 0.5);
  std::vector<Station> yarn;
  for (size_t k = 0; k < n; ++k) {
    std::vector<Station>& piece = pieces[k];
    const size_t last = piece.size() - 1;
    const Station zero = difference(piece.front(), piece.front());
    const Station top = k > 0 ? difference(seam[k], piece.front()) : zero;
    const Station bottom = k + 1 < n ? difference(seam[k + 1], piece.back()) : zero;
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

// Sweeps a yarn as a capped tube: station s at run position run0 + s run_step along `run`, its
// centre `nominal` sideways plus its offset along `side`, radii turning from `side` toward +z.
void sweep(TriMesh& mesh, const std::vector<Station>& yarn, int sides, const glm::dvec3& run,
           const glm::dvec3& side, const glm::dvec3& start, double run_step, int32_t element) {
  const int32_t first = static_cast<int32_t>(mesh.positions.size());
  const size_t first_face = mesh.triangles.size();
  const glm::dvec3 up(0.0, 0.0, 1.0);
  std::vector<Vec3> centres;
  for (size_t s = 0; s < yarn.size(); ++s) {
    const glm::dvec3 c = start + run * (run_step * static_cast<double>(s)) + side * yarn[s].side + up * yarn[s].z;
    centres.push_back(c);
    for (int k = 0; k < sides; ++k) {
      const double a = 2.0 * kPi * k / sides;
      mesh.positions.push_back(c + yarn[s].radius[k] * (std::cos(a) * side + std::sin(a) * up));
    }
  }
  const auto at = [&](size_t s, int k) { return first + static_cast<int32_t>(s * sides + (k % sides)); };
  for (size_t s = 0; s + 1 < yarn.size(); ++s)
    for (int k = 0; k < sides; ++k) {
      mesh.triangles.push_back({at(s, k), at(s + 1, k), at(s + 1, k + 1)});
      mesh.triangles.push_back({at(s, k), at(s + 1, k + 1), at(s, k + 1)});
    }
  const int32_t head = static_cast<int32_t>(mesh.positions.size()), tail = head + 1;
  mesh.positions.push_back(centres.front());
  mesh.positions.push_back(centres.back());
  const size_t end = yarn.size() - 1;
  for (int k = 0; k < sides; ++k) {
    mesh.triangles.push_back({head, at(0, k), at(0, k + 1)});
    mesh.triangles.push_back({tail, at(end, k + 1), at(end, k)});
  }
  // Outward: a positive enclosed volume.
  double volume = 0.0;
  for (size_t f = first_face; f < mesh.triangles.size(); ++f) {
    const Tri& t = mesh.triangles[f];
    volume += glm::dot(mesh.positions[t[0]], glm::cross(mesh.positions[t[1]], mesh.positions[t[2]]));
  }
  if (volume < 0.0)
    for (size_t f = first_face; f < mesh.triangles.size(); ++f) std::swap(mesh.triangles[f][1], mesh.triangles[f][2]);
  mesh.elements.resize(mesh.triangles.size(), element);
}

// Where blocks from different exemplars, or inconsistent ones, meet, the two yarns of a crossing
// may come closer than their radii allow. Over the stations of each yarn that pass over (or
// under) the other's cross-section, the shortfall in height is measured against that section's
// height at that distance from its centre; the upper yarn is raised and the lower one lowered by
// half of it each, over a raised-cosine bump a pitch to either side, until none is short.
void separate_crossings(std::vector<std::vector<Station>>& warps, std::vector<std::vector<Station>>& wefts, int pp,
                        int sides, double warp_step, double weft_step) {
  const int rows = static_cast<int>(wefts.size()), columns = static_cast<int>(warps.size());
  const size_t up_k = static_cast<size_t>(sides / 4), down_k = static_cast<size_t>(3 * sides / 4);
  const auto bump = [&](std::vector<Station>& yarn, int centre, double lift) {
    for (int d = -pp; d <= pp; ++d) {
      const int s = centre + d;
      if (s >= 0 && s < static_cast<int>(yarn.size())) yarn[s].z += lift * 0.5 * (1.0 + std::cos(kPi * d / pp));
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

}  // namespace

LoomFabric weave_fabric(const LoomDesign& design, const LoomAssignment& assignment,
                        const std::vector<ExemplarProfiles>& exemplars) {
  LoomFabric out;
  const glm::dvec2 pitch = exemplars[0].weave.pitch;
  const int pp = exemplars[0].per_pitch, sides = exemplars[0].sides;
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
  std::vector<std::vector<Station>> warps, wefts;
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
    warps.push_back(join_pieces(pieces));
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
    wefts.push_back(join_pieces(pieces));
  }
  separate_crossings(warps, wefts, pp, sides, pitch.y / pp, pitch.x / pp);
  for (int c = 0; c < design.columns; ++c) {
    const glm::dvec2 top = grid.origin + static_cast<double>(c) * grid.column_step - 0.5 * grid.row_step;
    sweep(out.mesh, warps[c], sides, glm::dvec3(0.0, -1.0, 0.0), glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(top, 0.0),
          pitch.y / pp, c);
  }
  for (int r = 0; r < design.rows; ++r) {
    const glm::dvec2 left = grid.origin + static_cast<double>(r) * grid.row_step - 0.5 * grid.column_step;
    sweep(out.mesh, wefts[r], sides, glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(left, 0.0),
          pitch.x / pp, design.columns + r);
  }
  return out;
}

}  // namespace meshquilt
