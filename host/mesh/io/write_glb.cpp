//! Writing binary glTF 2.0 (.glb): one mesh, one triangle primitive, with the element and source
//! of each face as the custom vertex attributes _ELEMENT and _SOURCE (float scalars: glTF allows
//! unsigned ints for indices only, and floats hold ids below 2^24 exactly) and vertex colours as
//! COLOR_0, and each vertex's swatch vertex as _ORIGIN where the mesh has them. A vertex whose faces differ in element or source is split, so each face's three
//! corners carry its own ids. With a texture, corners also split where faces give a vertex different
//! texture coordinates (TEXCOORD_0), and the PNG is embedded as the material's base colour.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <vector>

#include <glm/vec2.hpp>

#include "mesh/io/formats.h"

namespace meshquilt::io {
namespace {

template <typename T>
void append_raw(std::string& out, const T& value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

void pad(std::string& out, char with) {
  while (out.size() % 4 != 0) out += with;
}

// glTF colours are linear; the mesh's are sRGB bytes.
float linear(uint8_t c) {
  const double s = c / 255.0;
  return static_cast<float>(s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4));
}

}  // namespace

std::string format_glb(const TriMesh& mesh, const GlbTexture* texture) {
  const bool with_elements = mesh.elements.size() == mesh.triangles.size() && !mesh.elements.empty();
  const bool with_sources = mesh.sources.size() == mesh.triangles.size() && !mesh.sources.empty();
  const bool with_colors = mesh.colors.size() == mesh.positions.size() && !mesh.colors.empty();
  // Corners keyed by (vertex, element, source, texture coordinates): split where faces disagree.
  using Corner = std::tuple<int32_t, int32_t, int32_t, float, float>;
  std::map<Corner, uint32_t> corner_index;
  std::vector<Corner> corners;
  std::vector<uint32_t> indices;
  indices.reserve(3 * mesh.triangles.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int32_t v = mesh.triangles[f][k];
      const glm::vec2 uv = texture ? texture->face_uv[f][k] : glm::vec2(0.0f);
      const Corner key{v, with_elements ? mesh.elements[f] : 0, with_sources ? mesh.sources[f] : 0, uv.x, uv.y};
      const auto [it, added] = corner_index.emplace(key, static_cast<uint32_t>(corners.size()));
      if (added) corners.push_back(key);
      indices.push_back(it->second);
    }

  std::string bin;
  nlohmann::json views = nlohmann::json::array(), accessors = nlohmann::json::array(), attributes;
  const auto add_view = [&](size_t begin, int target) {
    views.push_back(
        {{"buffer", 0}, {"byteOffset", begin}, {"byteLength", bin.size() - begin}, {"target", target}});
    pad(bin, '\0');
    return static_cast<int>(views.size()) - 1;
  };
  const auto add_accessor = [&](int view, int component, size_t count, const char* type) {
    accessors.push_back(
        {{"bufferView", view}, {"componentType", component}, {"count", count}, {"type", type}});
    return static_cast<int>(accessors.size()) - 1;
  };
  constexpr int kFloat = 5126, kUnsignedInt = 5125, kArrayBuffer = 34962, kElementArrayBuffer = 34963;

  size_t begin = bin.size();
  std::vector<float> lo(3, std::numeric_limits<float>::max()), hi(3, std::numeric_limits<float>::lowest());
  for (const auto& [v, e, s, tu, tv] : corners) {
    const Vec3& p = mesh.positions[v];
    for (int k = 0; k < 3; ++k) {
      const auto x = static_cast<float>(p[k]);
      lo[k] = std::min(lo[k], x);
      hi[k] = std::max(hi[k], x);
      append_raw(bin, x);
    }
  }
  attributes["POSITION"] = add_accessor(add_view(begin, kArrayBuffer), kFloat, corners.size(), "VEC3");
  if (!corners.empty()) {
    accessors.back()["min"] = lo;
    accessors.back()["max"] = hi;
  }
  if (with_colors) {
    begin = bin.size();
    for (const auto& [v, e, s, tu, tv] : corners)
      for (uint8_t c : mesh.colors[v]) append_raw(bin, linear(c));
    attributes["COLOR_0"] = add_accessor(add_view(begin, kArrayBuffer), kFloat, corners.size(), "VEC3");
  }
  if (with_elements) {
    begin = bin.size();
    for (const auto& [v, e, s, tu, tv] : corners) append_raw(bin, static_cast<float>(e));
    attributes["_ELEMENT"] = add_accessor(add_view(begin, kArrayBuffer), kFloat, corners.size(), "SCALAR");
  }
  if (mesh.origins.size() == mesh.positions.size() && !mesh.origins.empty()) {
    begin = bin.size();
    for (const auto& [v, e, s, tu, tv] : corners) append_raw(bin, static_cast<float>(mesh.origins[v]));
    attributes["_ORIGIN"] = add_accessor(add_view(begin, kArrayBuffer), kFloat, corners.size(), "SCALAR");
  }
  if (with_sources) {
    begin = bin.size();
    for (const auto& [v, e, s, tu, tv] : corners) append_raw(bin, static_cast<float>(s));
    attributes["_SOURCE"] = add_accessor(add_view(begin, kArrayBuffer), kFloat, corners.size(), "SCALAR");
  }
  if (texture) {
    begin = bin.size();
    for (const auto& [v, e, s, tu, tv] : corners) {
      append_raw(bin, tu);
      append_raw(bin, tv);
    }
    attributes["TEXCOORD_0"] = add_accessor(add_view(begin, kArrayBuffer), kFloat, corners.size(), "VEC2");
  }
  begin = bin.size();
  for (uint32_t i : indices) append_raw(bin, i);
  const int index_accessor =
      add_accessor(add_view(begin, kElementArrayBuffer), kUnsignedInt, indices.size(), "SCALAR");

  nlohmann::json primitive = {{"attributes", attributes}, {"indices", index_accessor}, {"mode", 4}};
  int image_view = -1;
  if (texture) {
    begin = bin.size();
    bin += texture->png;
    image_view = static_cast<int>(views.size());
    views.push_back({{"buffer", 0}, {"byteOffset", begin}, {"byteLength", texture->png.size()}});
    pad(bin, '\0');
    primitive["material"] = 0;
  }
  nlohmann::json gltf = {
      {"asset", {{"version", "2.0"}, {"generator", "meshquilt"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}, {"name", "meshquilt"}}}},
      {"meshes",
       {{{"name", "meshquilt"},
         {"primitives", {primitive}}}}},
      {"buffers", {{{"byteLength", bin.size()}}}},
      {"bufferViews", views},
      {"accessors", accessors},
  };
  if (texture) {
    constexpr int kLinear = 9729, kRepeat = 10497;
    gltf["images"] = {{{"bufferView", image_view}, {"mimeType", "image/png"}}};
    gltf["samplers"] = {{{"magFilter", kLinear}, {"minFilter", kLinear}, {"wrapS", kRepeat}, {"wrapT", kRepeat}}};
    gltf["textures"] = {{{"source", 0}, {"sampler", 0}}};
    gltf["materials"] = {{{"name", "meshquilt"},
                          {"pbrMetallicRoughness",
                           {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}}}}};
  }
  std::string json = gltf.dump();
  pad(json, ' ');
  std::string out;
  out.reserve(12 + 8 + json.size() + 8 + bin.size());
  append_raw(out, uint32_t{0x46546C67});  // "glTF"
  append_raw(out, uint32_t{2});
  append_raw(out, static_cast<uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  append_raw(out, static_cast<uint32_t>(json.size()));
  append_raw(out, uint32_t{0x4E4F534A});  // "JSON"
  out += json;
  append_raw(out, static_cast<uint32_t>(bin.size()));
  append_raw(out, uint32_t{0x004E4942});  // "BIN\0"
  out += bin;
  return out;
}

}  // namespace meshquilt::io
