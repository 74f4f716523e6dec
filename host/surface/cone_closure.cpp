#include "surface/cone_closure.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "inspect/ring_links.h"

namespace meshquilt {
namespace {

// Centre lines nearer than this share of the clearance belong to wires through each other.
constexpr double kThrough = 0.5;

// Least distance between segments p1-q1 and p2-q2 (Ericson, Real-Time Collision Detection 5.1.9).
double segment_segment_distance(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
  double s = 0.0, t = 0.0;
  if (a <= 0.0 && e <= 0.0) return glm::length(r);
  if (a <= 0.0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = glm::dot(d1, r);
    if (e <= 0.0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = glm::dot(d1, d2), denom = a * e - b * b;
      s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return glm::length(p1 + s * d1 - (p2 + t * d2));
}

// Whether closed polylines a and b come nearer than d; segments whose bounding balls stay d apart
// are skipped.
bool nearer_than(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double d) {
  for (size_t i = 0; i < a.size(); ++i) {
    const Vec3 &a1 = a[i], &a2 = a[(i + 1) % a.size()];
    const Vec3 am = 0.5 * (a1 + a2);
    const double ar = 0.5 * glm::length(a2 - a1);
    for (size_t j = 0; j < b.size(); ++j) {
      const Vec3 &b1 = b[j], &b2 = b[(j + 1) % b.size()];
      if (glm::length(0.5 * (b1 + b2) - am) - ar - 0.5 * glm::length(b2 - b1) >= d) continue;
      if (segment_segment_distance(a1, a2, b1, b2) < d) return true;
    }
  }
  return false;
}

// Two rings apart, linked, nearer than the clearance (`close`: no ring is added so), or through
// each other (`meet`: wires crossing, or wound through twice, which no mail holds). `added`: only
// whether they keep the clearance matters while they do not.
enum class Relation { apart, linked, close, meet };

Relation relate(const ClosureRing& a, const ClosureRing& b, double clearance, bool added = false) {
  if (glm::length(a.centre - b.centre) > a.reach + b.reach + clearance) return Relation::apart;
  if (added) {
    if (nearer_than(a.line, b.line, clearance)) return Relation::close;
  } else if (nearer_than(a.line, b.line, kThrough * clearance)) {
    return Relation::meet;
  }
  const double lk = std::abs(linking_number(a.line, b.line));
  if (lk > 1.5) return Relation::meet;
  if (!added && nearer_than(a.line, b.line, clearance)) return Relation::close;
  return lk > 0.5 ? Relation::linked : Relation::apart;
}

}  // namespace

ClosureRing closure_ring(std::vector<Vec3> line) {
  ClosureRing ring;
  ring.line = std::move(line);
  for (const Vec3& p : ring.line) ring.centre += p;
  if (!ring.line.empty()) ring.centre /= static_cast<double>(ring.line.size());
  for (const Vec3& p : ring.line) ring.reach = std::max(ring.reach, glm::length(p - ring.centre));
  return ring;
}

double centre_line_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double least = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j)
      least = std::min(least, segment_segment_distance(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()]));
  return least;
}

ClosurePlan plan_closure(const std::vector<ClosureRing>& rings, const std::vector<uint8_t>& core,
                         const ClosureCandidates& candidates_of, const ClosureOptions& options) {
  const int target = options.links;
  // Rings given, then those added: who links whom and who meets whom.
  std::vector<std::vector<int32_t>> linked(rings.size()), meets(rings.size());
  for (size_t i = 0; i < rings.size(); ++i)
    for (size_t j = i + 1; j < rings.size(); ++j) {
      const Relation r = relate(rings[i], rings[j], options.clearance);
      if (r == Relation::apart || r == Relation::close) continue;
      auto& list = r == Relation::linked ? linked : meets;
      list[i].push_back(static_cast<int32_t>(j));
      list[j].push_back(static_cast<int32_t>(i));
    }
  std::vector<uint8_t> alive(rings.size(), 1), counts(core);
  const auto alive_count = [&](const std::vector<int32_t>& of) {
    return static_cast<int>(std::count_if(of.begin(), of.end(), [&](int32_t k) { return alive[k] != 0; }));
  };
  const auto short_rings = [&] {
    int n = 0;
    for (size_t i = 0; i < alive.size(); ++i)
      if (alive[i] && counts[i] && (alive_count(linked[i]) < target - 1 || alive_count(meets[i]) > 0)) ++n;
    return n;
  };
  ClosurePlan plan;
  plan.short_before = short_rings();

  // Out first: core rings that meet others or link more than one over, the worst first.
  for (;;) {
    int32_t worst = -1;
    int worst_score = 0;
    for (size_t i = 0; i < rings.size(); ++i) {
      if (!alive[i] || !core[i]) continue;
      const int score = 2 * alive_count(meets[i]) + std::max(0, alive_count(linked[i]) - (target + 1));
      if (score > worst_score) {
        worst_score = score;
        worst = static_cast<int32_t>(i);
      }
    }
    if (worst < 0) break;
    alive[worst] = 0;
    plan.removed.push_back(worst);
  }

  // A ring is added only where a core ring links fewer than one under the pattern's count.
  int short_of_links = 0;
  for (size_t i = 0; i < rings.size(); ++i) short_of_links += alive[i] && core[i] && alive_count(linked[i]) < target - 1;
  if (short_of_links == 0) {
    plan.short_after = short_rings();
    return plan;
  }
  // Each candidate against the rings given, once; against those added as they come.
  const std::vector<ClosureRing> candidates = candidates_of(alive);
  std::vector<std::vector<std::pair<int32_t, Relation>>> near(candidates.size());
  std::vector<uint8_t> used(candidates.size(), 0);
  for (size_t c = 0; c < candidates.size(); ++c)
    for (size_t i = 0; i < rings.size(); ++i) {
      if (!alive[i]) continue;
      const Relation r = relate(candidates[c], rings[i], options.clearance, true);
      if (r == Relation::close || r == Relation::meet) {
        used[c] = 1;  // never clear: rings kept are not taken out later
        break;
      }
      if (r != Relation::apart) near[c].emplace_back(static_cast<int32_t>(i), r);
    }
  std::vector<ClosureRing> all = rings;
  for (int round = 0; round < options.max_added; ++round) {
    int32_t best = -1;
    int best_score = 0;
    std::vector<int32_t> best_links;
    for (size_t c = 0; c < candidates.size(); ++c) {
      if (used[c]) continue;
      std::vector<int32_t> links;
      bool clear = true;
      const auto take = [&](int32_t i, Relation r) {
        if (!alive[i]) return;
        if (r == Relation::close || r == Relation::meet) clear = false;
        if (r == Relation::linked) links.push_back(i);
      };
      for (const auto& [i, r] : near[c]) take(i, r);
      for (size_t i = rings.size(); clear && i < all.size(); ++i)
        take(static_cast<int32_t>(i), relate(candidates[c], all[i], options.clearance, true));
      if (!clear || static_cast<int>(links.size()) < target - 1) continue;
      int short_linked = 0, wanting = 0;
      bool over = false;
      for (int32_t i : links) {
        const int have = alive_count(linked[i]);
        if (have >= target + 1) over = true;
        if (counts[i] && have < target) ++wanting;
        if (counts[i] && have < target - 1) ++short_linked;
      }
      if (over || short_linked == 0 || wanting < 2) continue;
      // Rings under the pattern's count first, then more links.
      const int score = 16 * wanting + static_cast<int>(links.size());
      if (score > best_score) {
        best_score = score;
        best = static_cast<int32_t>(c);
        best_links = std::move(links);
      }
    }
    if (best < 0) break;
    used[best] = 1;
    const auto index = static_cast<int32_t>(all.size());
    all.push_back(candidates[best]);
    alive.push_back(1);
    counts.push_back(1);
    linked.emplace_back(best_links);
    meets.emplace_back();
    for (int32_t i : best_links) linked[i].push_back(index);
    plan.added.push_back(best);
  }
  plan.short_after = short_rings();
  return plan;
}

}  // namespace meshquilt
