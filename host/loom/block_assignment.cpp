#include "loom/block_assignment.h"

#include <algorithm>
#include <array>
#include <limits>

#include "core/error.h"

namespace meshquilt {
namespace {

// Neighbours in the design: up (r - 1), down (r + 1), left (c - 1), right (c + 1), and the
// exemplar's crossing each maps to from (x, y): row r - 1 is weft y + 1.
constexpr std::array<int, 4> kDr{-1, 1, 0, 0}, kDc{0, 0, -1, 1};

uint64_t mix(uint64_t h) {
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ULL;
  return h ^ (h >> 33);
}

uint64_t hash_of(uint64_t seed, uint64_t a, uint64_t b, uint64_t c) {
  return mix(mix(mix(seed + 0x9e3779b97f4a7c15ULL) ^ a) ^ (b * 0x100000001b3ULL)) ^ c;
}

// A block's centre and its four neighbours as bits 0..4.
int block_code(const WeavePattern& p, int x, int y) {
  int code = p.over(x, y) ? 1 : 0;
  for (int k = 0; k < 4; ++k)
    if (p.over(x + kDc[k], y - kDr[k])) code |= 2 << k;
  return code;
}

// Neighbour k of crossing (r, c), wrapping round the edges when periodic; false past an edge.
bool neighbour(const LoomDesign& d, int r, int c, int k, bool periodic, int& rr, int& cc) {
  rr = r + kDr[k];
  cc = c + kDc[k];
  if (periodic) {
    rr = (rr + d.rows) % d.rows;
    cc = (cc + d.columns) % d.columns;
  }
  return rr >= 0 && rr < d.rows && cc >= 0 && cc < d.columns;
}

// The design's code at (r, c) and which neighbours it has (all four, wrapping, when periodic).
std::pair<int, int> design_code(const LoomDesign& d, int r, int c, bool periodic) {
  int code = d.at(r, c) ? 1 : 0, mask = 0;
  for (int k = 0; k < 4; ++k) {
    int rr, cc;
    if (!neighbour(d, r, c, k, periodic, rr, cc)) continue;
    mask |= 1 << k;
    if (d.at(rr, cc)) code |= 2 << k;
  }
  return {code, mask};
}

struct Candidates {
  std::vector<LoomBlock> blocks;
  std::vector<int> codes;
  std::vector<std::vector<int32_t>> id_of;  // per exemplar, y * warps + x -> id or -1
  std::array<std::vector<int32_t>, 512> best;   // per design code + 32 * mask: the most consistent
  std::array<std::vector<int32_t>, 2> correct;  // per centre bit: every correct block

  int32_t id(const std::vector<WeavePattern>& ex, const LoomBlock& b) const {
    const WeavePattern& p = ex[b.exemplar];
    if (b.x < 1 || b.y < 1 || b.x > p.warps - 2 || b.y > p.wefts - 2) return -1;
    return id_of[b.exemplar][static_cast<size_t>(b.y) * p.warps + b.x];
  }
};

Candidates interior_blocks(const std::vector<WeavePattern>& exemplars) {
  Candidates c;
  for (size_t u = 0; u < exemplars.size(); ++u) {
    const WeavePattern& p = exemplars[u];
    c.id_of.emplace_back(static_cast<size_t>(p.warps) * p.wefts, -1);
    for (int y = 1; y + 1 < p.wefts; ++y)
      for (int x = 1; x + 1 < p.warps; ++x) {
        c.id_of[u][static_cast<size_t>(y) * p.warps + x] = static_cast<int32_t>(c.blocks.size());
        c.blocks.push_back({static_cast<int32_t>(u), x, y});
        c.codes.push_back(block_code(p, x, y));
      }
  }
  for (int32_t t = 0; t < static_cast<int32_t>(c.blocks.size()); ++t) c.correct[c.codes[t] & 1].push_back(t);
  for (int mask = 0; mask < 16; ++mask)
    for (int code = 0; code < 32; ++code) {
      if ((code >> 1) & ~mask) continue;  // a missing neighbour has no bit
      std::vector<int32_t>& best = c.best[code + 32 * mask];
      int top = -1;
      for (int32_t t : c.correct[code & 1]) {
        const int matches = __builtin_popcount(~((c.codes[t] ^ code) >> 1) & mask);
        if (matches > top) best.clear();
        if (matches >= top) {
          top = matches;
          best.push_back(t);
        }
      }
    }
  return c;
}

// The one of `list` (ids) with the largest score, ties to the smallest hash at (r, c).
template <typename Score>
int32_t pick(const std::vector<int32_t>& list, Score score, uint64_t seed, int r, int c) {
  int32_t chosen = -1;
  long best = std::numeric_limits<long>::min();
  uint64_t best_hash = 0;
  for (size_t k = 0; k < list.size(); ++k) {
    const long s = score(k);
    const uint64_t h = hash_of(seed, static_cast<uint64_t>(r), static_cast<uint64_t>(c), static_cast<uint64_t>(list[k]));
    if (s > best || (s == best && h < best_hash)) {
      best = s;
      best_hash = h;
      chosen = static_cast<int32_t>(k);
    }
  }
  return chosen;
}

// Shifts (sx, sy) under which exemplar `p` reads the same wherever both crossings lie in it,
// overlapping it by at least 3 x 3; (0, 0) first.
std::vector<std::pair<int, int>> symmetries(const WeavePattern& p) {
  std::vector<std::pair<int, int>> shifts{{0, 0}};
  for (int sy = -(p.wefts - 3); sy <= p.wefts - 3; ++sy)
    for (int sx = -(p.warps - 3); sx <= p.warps - 3; ++sx) {
      if (sx == 0 && sy == 0) continue;
      bool same = true;
      for (int y = std::max(0, -sy); same && y < std::min(p.wefts, p.wefts - sy); ++y)
        for (int x = std::max(0, -sx); same && x < std::min(p.warps, p.warps - sx); ++x)
          same = p.over(x, y) == p.over(x + sx, y + sy);
      if (same) shifts.emplace_back(sx, sy);
    }
  return shifts;
}

}  // namespace

LoomAssignment assign_blocks(const LoomDesign& design, const std::vector<WeavePattern>& exemplars,
                             const AssignmentOptions& options) {
  const Candidates cand = interior_blocks(exemplars);
  for (int bit = 0; bit < 2; ++bit)
    if (cand.correct[bit].empty() && std::find(design.warp_over.begin(), design.warp_over.end(), bit) !=
                                         design.warp_over.end())
      throw InputError(std::string("the exemplars have no block with the ") + (bit ? "warp" : "weft") +
                           " on top (away from their edges), which the design asks for",
                       ErrorKind::invalid_option);
  LoomAssignment out;
  out.rows = design.rows;
  out.columns = design.columns;
  out.blocks.resize(static_cast<size_t>(design.rows) * design.columns);
  const auto list_at = [&](int r, int c) -> const std::vector<int32_t>& {
    const auto [code, mask] = design_code(design, r, c, options.periodic);
    return options.method == AssignmentMethod::naive ? cand.correct[code & 1] : cand.best[code + 32 * mask];
  };
  const auto none = [](size_t) { return 0L; };
  if (options.method != AssignmentMethod::structured) {
    for (int r = 0; r < design.rows; ++r)
      for (int c = 0; c < design.columns; ++c) {
        const std::vector<int32_t>& list = list_at(r, c);
        out.blocks[static_cast<size_t>(r) * design.columns + c] = cand.blocks[list[pick(list, none, options.seed, r, c)]];
      }
    return out;
  }

  // Along each warp (column), the most continuous chain of most consistent blocks:
  // f(r, t) = max(max f(r - 1, .), f(r - 1, t's block one weft up) + 1).
  std::vector<int32_t> position(cand.blocks.size(), -1);  // id -> index in the previous row's list
  std::vector<std::vector<int>> f(static_cast<size_t>(design.rows));
  std::vector<const std::vector<int32_t>*> lists(static_cast<size_t>(design.rows));
  std::vector<int32_t> predecessor(cand.blocks.size());
  for (size_t t = 0; t < cand.blocks.size(); ++t) {
    LoomBlock up = cand.blocks[t];
    ++up.y;
    predecessor[t] = cand.id(exemplars, up);
  }
  for (int c = 0; c < design.columns; ++c) {
    for (int r = 0; r < design.rows; ++r) {
      lists[r] = &list_at(r, c);
      f[r].assign(lists[r]->size(), 0);
      if (r == 0) continue;
      const std::vector<int32_t>& previous = *lists[r - 1];
      int top = 0;
      for (size_t k = 0; k < previous.size(); ++k) {
        position[previous[k]] = static_cast<int32_t>(k);
        top = std::max(top, f[r - 1][k]);
      }
      for (size_t k = 0; k < lists[r]->size(); ++k) {
        const int32_t p = predecessor[(*lists[r])[k]];
        const int32_t at = p >= 0 ? position[p] : -1;
        f[r][k] = at >= 0 ? std::max(top, f[r - 1][at] + 1) : top;
      }
      for (int32_t t : previous) position[t] = -1;
    }
    int32_t k = pick(*lists[design.rows - 1], [&](size_t i) { return static_cast<long>(f[design.rows - 1][i]); },
                     options.seed, design.rows - 1, c);
    for (int r = design.rows - 1;; --r) {
      const int32_t t = (*lists[r])[k];
      out.blocks[static_cast<size_t>(r) * design.columns + c] = cand.blocks[t];
      if (r == 0) break;
      const std::vector<int32_t>& previous = *lists[r - 1];
      const int32_t p = predecessor[t];
      const auto it = p >= 0 ? std::find(previous.begin(), previous.end(), p) : previous.end();
      if (it != previous.end() && f[r - 1][it - previous.begin()] + 1 == f[r][k])
        k = static_cast<int32_t>(it - previous.begin());
      else
        k = pick(previous, [&](size_t i) { return static_cast<long>(f[r - 1][i]); }, options.seed, r - 1, c);
    }
  }

  // Randomization: the blocks of one exemplar in each shift_block x shift_block square move by one
  // of its symmetries, the first from a random start under which every one of them reads the
  // same, so the square keeps its continuity and consistency.
  std::vector<std::vector<std::pair<int, int>>> shifts;
  for (const WeavePattern& p : exemplars) shifts.push_back(symmetries(p));
  const int side = std::max(1, std::min(options.shift_block, std::max(design.rows, design.columns)));
  for (int r0 = 0; r0 < design.rows; r0 += side)
    for (int c0 = 0; c0 < design.columns; c0 += side)
      for (size_t u = 0; u < exemplars.size(); ++u) {
        const auto& s = shifts[u];
        const uint64_t start = hash_of(options.seed ^ 0x5bd1e995ULL, static_cast<uint64_t>(r0),
                                       static_cast<uint64_t>(c0), u) % s.size();
        const int r1 = std::min(design.rows, r0 + side), c1 = std::min(design.columns, c0 + side);
        const auto fits = [&](int sx, int sy) {
          for (int r = r0; r < r1; ++r)
            for (int c = c0; c < c1; ++c) {
              const LoomBlock& b = out.blocks[static_cast<size_t>(r) * design.columns + c];
              if (b.exemplar != static_cast<int32_t>(u)) continue;
              const int32_t to = cand.id(exemplars, {b.exemplar, b.x + sx, b.y + sy});
              if (to < 0 || cand.codes[to] != cand.codes[cand.id(exemplars, b)]) return false;
            }
          return true;
        };
        for (size_t k = 0; k < s.size(); ++k) {
          const auto [sx, sy] = s[(start + k) % s.size()];
          if (!fits(sx, sy)) continue;
          for (int r = r0; r < r1; ++r)
            for (int c = c0; c < c1; ++c) {
              LoomBlock& b = out.blocks[static_cast<size_t>(r) * design.columns + c];
              if (b.exemplar == static_cast<int32_t>(u)) b = {b.exemplar, b.x + sx, b.y + sy};
            }
          break;
        }
      }
  return out;
}

AssignmentScores score_assignment(const LoomDesign& design, const std::vector<WeavePattern>& exemplars,
                                  const LoomAssignment& a, bool periodic) {
  AssignmentScores s;
  long correct = 0, consistent = 0, pairs = 0, continuing = 0, warp_pairs = 0, warp_continuing = 0;
  for (int r = 0; r < design.rows; ++r)
    for (int c = 0; c < design.columns; ++c) {
      const LoomBlock& b = a.at(r, c);
      const WeavePattern& p = exemplars[b.exemplar];
      correct += p.over(b.x, b.y) == design.at(r, c);
      bool agree = true;
      for (int k = 0; k < 4; ++k) {
        int rr, cc;
        if (!neighbour(design, r, c, k, periodic, rr, cc)) continue;
        agree = agree && p.over(b.x + kDc[k], b.y - kDr[k]) == design.at(rr, cc);
        if (k == 1 || k == 3) {  // each pair once: down and right
          const LoomBlock& n = a.at(rr, cc);
          const bool continues = n.exemplar == b.exemplar && n.x == b.x + kDc[k] && n.y == b.y - kDr[k];
          ++pairs;
          continuing += continues;
          if (k == 1) {
            ++warp_pairs;
            warp_continuing += continues;
          }
        }
      }
      consistent += agree;
    }
  const double n = static_cast<double>(design.rows) * design.columns;
  s.correct = n > 0 ? correct / n : 0.0;
  s.consistent = n > 0 ? consistent / n : 0.0;
  s.continuous = pairs > 0 ? static_cast<double>(continuing) / pairs : 0.0;
  s.continuous_along_warps = warp_pairs > 0 ? static_cast<double>(warp_continuing) / warp_pairs : 0.0;
  return s;
}

}  // namespace meshquilt
