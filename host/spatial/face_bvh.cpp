#include "spatial/face_bvh.h"

#include <embree3/rtcore.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>

#include "core/error.h"

namespace meshquilt {
namespace {

// Embree's BVH is float: boxes are rounded outward and query radii padded by this relative
// margin (far above float rounding), so the float traversal never prunes a face the exact
// double test would keep.
constexpr double kRelativeSlack = 1e-5;

float round_down(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -INFINITY) : f;
}

float round_up(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, INFINITY) : f;
}

struct Box {
  Vec3 lo, hi;
};

Box face_box(const TriMesh& mesh, int32_t f) {
  const Tri& t = mesh.triangles[f];
  const Vec3& a = mesh.positions[t[0]];
  const Vec3& b = mesh.positions[t[1]];
  const Vec3& c = mesh.positions[t[2]];
  return {glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c))};
}

bool boxes_overlap(const Box& a, const Box& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y &&
         a.lo.z <= b.hi.z && b.lo.z <= a.hi.z;
}

// State of one point query; Embree hands it back to the callback through userPtr.
struct QueryState {
  const TriMesh* mesh = nullptr;
  const int32_t* faces_of = nullptr;  // the mesh face of each primitive; null: the primitive's index
  Vec3 p{0.0};
  Vec3 offset{0.0};  // min cost queries: the faces' corners are positions + offset
  bool moved = false;
  double slack = 0.0;  // absolute padding for float rounding of the query point and boxes
  // Closest point / min cost queries.
  ClosestPoint best;
  double best_cost = std::numeric_limits<double>::infinity();
  double max_distance = std::numeric_limits<double>::infinity();
  const std::function<double(const ClosestPoint&)>* cost = nullptr;
  const std::function<double(double)>* radius_for = nullptr;
  const std::function<double(int32_t)>* face_bound = nullptr;  // may be empty
  // Box queries.
  const std::vector<Box>* boxes = nullptr;
  Box box;
  std::vector<int32_t>* faces = nullptr;
};

float padded_radius(double r, double slack) {
  if (!std::isfinite(r)) return INFINITY;
  return round_up(r * (1.0 + kRelativeSlack) + slack);
}

ClosestPoint closest_on_face(const TriMesh& mesh, int32_t f, const Vec3& p) {
  const Tri& t = mesh.triangles[f];
  ClosestPoint cp = closest_point_on_triangle(p, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
  cp.face = f;
  return cp;
}

int32_t face_of(const int32_t* faces_of, unsigned primitive) {
  return faces_of ? faces_of[primitive] : static_cast<int32_t>(primitive);
}

bool closest_point_callback(RTCPointQueryFunctionArguments* args) {
  auto* q = static_cast<QueryState*>(args->userPtr);
  const int32_t f = face_of(q->faces_of, args->primID);
  const ClosestPoint cp = closest_on_face(*q->mesh, f, q->p);
  if (cp.distance > q->max_distance) return false;
  // Ties go to the lower face index so results do not depend on traversal order.
  if (cp.distance < q->best.distance || (cp.distance == q->best.distance && f < q->best.face)) {
    q->best = cp;
    const float r = padded_radius(cp.distance, q->slack);
    if (r < args->query->radius) {
      args->query->radius = r;
      return true;
    }
  }
  return false;
}

bool min_cost_callback(RTCPointQueryFunctionArguments* args) {
  auto* q = static_cast<QueryState*>(args->userPtr);
  const int32_t f = face_of(q->faces_of, args->primID);
  if (*q->face_bound && (*q->face_bound)(f) > q->best_cost) return false;  // cannot beat or tie it
  ClosestPoint cp;
  if (q->moved) {
    const Tri& t = q->mesh->triangles[f];
    const auto& x = q->mesh->positions;
    cp = closest_point_on_triangle(q->p, x[t[0]] + q->offset, x[t[1]] + q->offset, x[t[2]] + q->offset);
    cp.face = f;
  } else {
    cp = closest_on_face(*q->mesh, f, q->p);
  }
  const double c = (*q->cost)(cp);
  if (c < q->best_cost || (c == q->best_cost && f < q->best.face)) {
    q->best_cost = c;
    q->best = cp;
    const float r = padded_radius((*q->radius_for)(c), q->slack);
    if (r < args->query->radius) {
      args->query->radius = r;
      return true;
    }
  }
  return false;
}

bool box_callback(RTCPointQueryFunctionArguments* args) {
  auto* q = static_cast<QueryState*>(args->userPtr);
  if (boxes_overlap((*q->boxes)[args->primID], q->box)) q->faces->push_back(face_of(q->faces_of, args->primID));
  return false;
}

void bounds_callback(const RTCBoundsFunctionArguments* args) {
  const auto* boxes = static_cast<const std::vector<Box>*>(args->geometryUserPtr);
  const Box& b = (*boxes)[args->primID];
  RTCBounds* o = args->bounds_o;
  o->lower_x = round_down(b.lo.x);
  o->lower_y = round_down(b.lo.y);
  o->lower_z = round_down(b.lo.z);
  o->upper_x = round_up(b.hi.x);
  o->upper_y = round_up(b.hi.y);
  o->upper_z = round_up(b.hi.z);
}

// State of one ray cast. Embree passes the context pointer to the intersect callback, so the
// context comes first and the callback casts back to the whole struct.
struct RayState {
  RTCIntersectContext context;
  const TriMesh* mesh = nullptr;
  const int32_t* faces_of = nullptr;
  Vec3 origin{0.0}, direction{0.0};
  double max_distance = std::numeric_limits<double>::infinity();
  double slack = 0.0;  // ray parameter padding for float rounding of the ray and the boxes
  RayHit best;
};

// Exact double test per candidate; Embree's float tfar only prunes, so it is shrunk to the best
// hit plus slack (a face at the same t with a lower index must still be visited).
void ray_intersect_callback(const RTCIntersectFunctionNArguments* args) {
  auto* q = reinterpret_cast<RayState*>(args->context);
  const int32_t f = face_of(q->faces_of, args->primID);
  const Tri& t = q->mesh->triangles[f];
  const double distance = ray_triangle(q->origin, q->direction, q->mesh->positions[t[0]],
                                      q->mesh->positions[t[1]], q->mesh->positions[t[2]]);
  if (!(distance <= q->max_distance)) return;
  if (distance < q->best.distance || (distance == q->best.distance && f < q->best.face)) {
    q->best = {f, distance};
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
    const float tfar = padded_radius(distance, q->slack);
    for (unsigned i = 0; i < args->N; ++i) {
      if (args->valid[i] && tfar < RTCRayN_tfar(rays, args->N, i)) RTCRayN_tfar(rays, args->N, i) = tfar;
    }
  }
}

// Occlusion queries are never made, but Embree requires the callback to be set.
void unused_occluded(const RTCOccludedFunctionNArguments*) {}

}  // namespace

struct FaceBvh::Impl {
  std::vector<int32_t> faces;  // of a subset, the mesh face of each primitive; empty: face k is primitive k
  const int32_t* faces_of() const { return faces.empty() ? nullptr : faces.data(); }
  std::vector<Box> boxes;  // per primitive, double precision
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  double slack = 0.0;
  // Embree reports errors through a C callback; the first one is kept and thrown after the call.
  std::mutex error_mutex;
  std::atomic<bool> has_error{false};  // lets queries skip the lock when all is well
  RTCError error_code = RTC_ERROR_NONE;
  std::string error_message;

  static void on_error(void* user, RTCError code, const char* message) {
    auto* self = static_cast<Impl*>(user);
    std::lock_guard<std::mutex> lock(self->error_mutex);
    if (self->error_code == RTC_ERROR_NONE) {
      self->error_code = code;
      self->error_message = message ? message : "";
      self->has_error = true;
    }
  }

  void check(const char* what) {
    if (!has_error.load(std::memory_order_acquire)) return;
    std::lock_guard<std::mutex> lock(error_mutex);
    if (error_code == RTC_ERROR_NONE) return;
    const std::string message = std::string("Embree ") + what + ": " + error_message + " (code " +
                                std::to_string(static_cast<int>(error_code)) + ")";
    const RTCError code = error_code;
    error_code = RTC_ERROR_NONE;
    has_error = false;
    if (code == RTC_ERROR_UNSUPPORTED_CPU || code == RTC_ERROR_OUT_OF_MEMORY) throw DeviceError(message);
    throw SolverError(message);
  }

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

double ray_triangle(const Vec3& origin, const Vec3& direction, const Vec3& a, const Vec3& b, const Vec3& c) {
  constexpr double kMiss = std::numeric_limits<double>::infinity();
  const Vec3 ab = b - a, ac = c - a;
  const Vec3 p = glm::cross(direction, ac);
  const double det = glm::dot(ab, p);
  if (det == 0.0 || !std::isfinite(det)) return kMiss;
  const double inv = 1.0 / det;
  const Vec3 s = origin - a;
  const double u = glm::dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return kMiss;
  const Vec3 q = glm::cross(s, ab);
  const double v = glm::dot(direction, q) * inv;
  if (v < 0.0 || u + v > 1.0) return kMiss;
  const double t = glm::dot(ac, q) * inv;
  return t > 0.0 ? t : kMiss;
}

FaceBvh::FaceBvh(const TriMesh& mesh, BvhQuality quality) : FaceBvh(mesh, {}, false, quality) {}

FaceBvh::FaceBvh(const TriMesh& mesh, std::vector<int32_t> faces, BvhQuality quality)
    : FaceBvh(mesh, std::move(faces), true, quality) {}

FaceBvh::FaceBvh(const TriMesh& mesh, std::vector<int32_t> faces, bool subset, BvhQuality quality)
    : mesh_(mesh), impl_(std::make_unique<Impl>()) {
  for (const int32_t f : faces) {
    if (f < 0 || static_cast<size_t>(f) >= mesh.num_faces())
      throw std::out_of_range("FaceBvh: face " + std::to_string(f) + " outside [0, " + std::to_string(mesh.num_faces()) + ")");
  }
  primitives_ = subset ? faces.size() : mesh.num_faces();
  impl_->faces = std::move(faces);
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) {
    throw DeviceError("Embree: cannot create a device (" + std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")");
  }
  rtcSetDeviceErrorFunction(impl_->device, &Impl::on_error, impl_.get());

  double scale = 0.0;
  for (const Vec3& v : mesh.positions) scale = std::max(scale, std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z))));
  impl_->slack = 8.0 * kRelativeSlack * scale + 1e-30;

  // User geometry: bounds come from the double positions rounded outward, so no float copy of
  // the vertices (and no padding after a vertex buffer) is needed, and every exact test runs on
  // the mesh's own doubles.
  impl_->scene = rtcNewScene(impl_->device);
  rtcSetSceneBuildQuality(impl_->scene, quality == BvhQuality::low ? RTC_BUILD_QUALITY_LOW : RTC_BUILD_QUALITY_MEDIUM);
  RTCGeometry geometry = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(primitives_));
  impl_->boxes.resize(primitives_);
  for (size_t k = 0; k < primitives_; ++k)
    impl_->boxes[k] = face_box(mesh, face_of(impl_->faces_of(), static_cast<unsigned>(k)));
  rtcSetGeometryUserData(geometry, &impl_->boxes);
  rtcSetGeometryBoundsFunction(geometry, &bounds_callback, nullptr);
  rtcSetGeometryIntersectFunction(geometry, &ray_intersect_callback);
  rtcSetGeometryOccludedFunction(geometry, &unused_occluded);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(impl_->scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(impl_->scene);
  impl_->check("scene build");
}

FaceBvh::~FaceBvh() = default;

ClosestPoint FaceBvh::closest_point(const Vec3& p, double max_distance) const {
  QueryState q;
  q.mesh = &mesh_;
  q.faces_of = impl_->faces_of();
  q.p = p;
  q.max_distance = max_distance;
  q.slack = impl_->slack + kRelativeSlack * std::max(std::abs(p.x), std::max(std::abs(p.y), std::abs(p.z)));
  if (primitives_ == 0) return q.best;
  RTCPointQuery query;
  query.x = static_cast<float>(p.x);
  query.y = static_cast<float>(p.y);
  query.z = static_cast<float>(p.z);
  query.time = 0.0f;
  query.radius = padded_radius(max_distance, q.slack);
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(impl_->scene, &query, &context, &closest_point_callback, &q);
  impl_->check("point query");
  return q.best;
}

ClosestPoint FaceBvh::min_cost_face(const Vec3& p, const std::function<double(const ClosestPoint&)>& cost,
                                    const std::function<double(double best_cost)>& radius_for,
                                    double* best_cost, double known_cost,
                                    const std::function<double(int32_t)>& face_bound, int32_t known_face,
                                    const Vec3& offset) const {
  QueryState q;
  q.mesh = &mesh_;
  q.faces_of = impl_->faces_of();
  q.p = p;
  q.offset = offset;
  q.moved = offset != Vec3(0.0);
  q.cost = &cost;
  q.radius_for = &radius_for;
  q.face_bound = &face_bound;
  q.best_cost = known_cost;
  q.best.face = known_face;  // a tie goes to a lower index only
  // The searched point is p - offset; the slack covers its rounding and that of the moved corners.
  const Vec3 at = p - offset;
  const double scale = std::max({std::abs(at.x), std::abs(at.y), std::abs(at.z), std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  q.slack = impl_->slack + kRelativeSlack * scale;
  if (primitives_ > 0) {
    RTCPointQuery query;
    query.x = static_cast<float>(at.x);
    query.y = static_cast<float>(at.y);
    query.z = static_cast<float>(at.z);
    query.time = 0.0f;
    query.radius = std::isfinite(known_cost) ? padded_radius(radius_for(known_cost), q.slack) : INFINITY;
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(impl_->scene, &query, &context, &min_cost_callback, &q);
    impl_->check("point query");
  }
  if (best_cost) *best_cost = q.best_cost;
  if (q.best.face == known_face) return ClosestPoint{};  // nothing beat the known face
  return q.best;
}

RayHit FaceBvh::ray_cast(const Vec3& origin, const Vec3& direction, double max_distance) const {
  RayState q;
  rtcInitIntersectContext(&q.context);
  q.mesh = &mesh_;
  q.faces_of = impl_->faces_of();
  q.origin = origin;
  q.direction = direction;
  q.max_distance = max_distance;
  if (primitives_ == 0) return q.best;
  // Rounding the ray to float moves it by about kRelativeSlack x (|origin| + t |direction|);
  // the slack, in units of t, covers that for every t up to the scene's size.
  const double length = glm::length(direction);
  const double scale = std::max(std::abs(origin.x), std::max(std::abs(origin.y), std::abs(origin.z)));
  q.slack = (impl_->slack + kRelativeSlack * scale) / length;
  RTCRayHit rayhit;
  rayhit.ray.org_x = static_cast<float>(origin.x);
  rayhit.ray.org_y = static_cast<float>(origin.y);
  rayhit.ray.org_z = static_cast<float>(origin.z);
  rayhit.ray.dir_x = static_cast<float>(direction.x);
  rayhit.ray.dir_y = static_cast<float>(direction.y);
  rayhit.ray.dir_z = static_cast<float>(direction.z);
  rayhit.ray.tnear = 0.0f;
  rayhit.ray.tfar = padded_radius(max_distance, q.slack);  // the same padding, infinity kept
  rayhit.ray.time = 0.0f;
  rayhit.ray.mask = 0xFFFFFFFFu;
  rayhit.ray.id = 0;
  rayhit.ray.flags = 0;
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &q.context, &rayhit);
  impl_->check("ray cast");
  return q.best;
}

void FaceBvh::faces_in_box(const Vec3& lo, const Vec3& hi, std::vector<int32_t>& faces) const {
  if (primitives_ == 0 || lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) return;
  QueryState q;
  q.mesh = &mesh_;
  q.faces_of = impl_->faces_of();
  q.box = {lo, hi};
  q.boxes = &impl_->boxes;
  q.faces = &faces;
  // The sphere around the box contains it, so every face box overlapping the box is visited;
  // the callback keeps only the exact overlaps.
  const Vec3 center = 0.5 * (lo + hi);
  q.slack = impl_->slack + kRelativeSlack * std::max(std::abs(center.x), std::max(std::abs(center.y), std::abs(center.z)));
  RTCPointQuery query;
  query.x = static_cast<float>(center.x);
  query.y = static_cast<float>(center.y);
  query.z = static_cast<float>(center.z);
  query.time = 0.0f;
  query.radius = padded_radius(0.5 * glm::length(hi - lo), q.slack);
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(impl_->scene, &query, &context, &box_callback, &q);
  impl_->check("box query");
}

namespace {
struct CollideState {
  const std::vector<Box>* boxes;
  const int32_t* faces_of;
  const std::function<void(int32_t, int32_t)>* visit;
};

void collide_callback(void* user, RTCCollision* collisions, unsigned count) {
  const auto* s = static_cast<const CollideState*>(user);
  for (unsigned i = 0; i < count; ++i) {
    const unsigned a = collisions[i].primID0, b = collisions[i].primID1;
    const int32_t f = face_of(s->faces_of, a), g = face_of(s->faces_of, b);
    // Embree reports each unordered leaf-level candidate in both orders; keep one and test the
    // exact double boxes.
    if (f < g && boxes_overlap((*s->boxes)[a], (*s->boxes)[b])) (*s->visit)(f, g);
  }
}
}  // namespace

void FaceBvh::for_each_overlapping_pair(const std::function<void(int32_t, int32_t)>& visit) const {
  if (primitives_ < 2) return;
  CollideState state{&impl_->boxes, impl_->faces_of(), &visit};
  rtcCollide(impl_->scene, impl_->scene, &collide_callback, &state);
  impl_->check("collision");
}

}  // namespace meshquilt
