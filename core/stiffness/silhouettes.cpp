#include "core/stiffness/silhouettes.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace mozzi::core::stiffness {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kCircleSides = 72;  // a wheel as a 72-gon: 5 degrees per side

Error bad(const std::string& message, const std::string& where) {
  return makeError(ErrorCode::ParseError, message, "silhouettes: " + where);
}

Result<Vector2> point(const nlohmann::json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number())
    return bad("a point is [x, z] in metres", where);
  const Vector2 p(j[0].get<double>(), j[1].get<double>());
  if (!p.allFinite()) return bad("non-finite coordinate", where);
  return p;
}

Result<std::string> text(const nlohmann::json& j, const char* key, const std::string& where, bool required = true) {
  if (!j.contains(key)) {
    if (required) return bad(std::string("missing \"") + key + "\"", where);
    return std::string();
  }
  if (!j[key].is_string()) return bad(std::string("\"") + key + "\" is not text", where);
  return j[key].get<std::string>();
}

Result<SilhouetteComponent> component(const std::string& key, const nlohmann::json& j) {
  const std::string where = "component " + key;
  if (!j.is_object()) return bad("a component is an object", where);
  SilhouetteComponent c;
  c.key = key;
  MOZZI_TRY_ASSIGN(c.name, text(j, "name", where));
  MOZZI_TRY_ASSIGN(c.source, text(j, "source", where));
  if (j.contains("polygons")) {
    if (!j["polygons"].is_array()) return bad("\"polygons\" is a list of point lists", where);
    for (std::size_t i = 0; i < j["polygons"].size(); ++i) {
      const auto& poly = j["polygons"][i];
      const std::string pw = where + ", polygon " + std::to_string(i + 1);
      if (!poly.is_array() || poly.size() < 3) return bad("a polygon needs at least 3 points", pw);
      std::vector<Vector2> pts;
      for (const auto& p : poly) {
        MOZZI_TRY_ASSIGN(auto v, point(p, pw));
        pts.push_back(v);
      }
      c.polygons.push_back(std::move(pts));
    }
  }
  if (j.contains("circles")) {
    if (!j["circles"].is_array()) return bad("\"circles\" is a list", where);
    for (std::size_t i = 0; i < j["circles"].size(); ++i) {
      const auto& circle = j["circles"][i];
      const std::string cw = where + ", circle " + std::to_string(i + 1);
      if (!circle.is_object() || !circle.contains("centre") || !circle.contains("radius") ||
          !circle["radius"].is_number())
        return bad("a circle is {\"centre\": [x, z], \"radius\": r}", cw);
      MOZZI_TRY_ASSIGN(auto centre, point(circle["centre"], cw));
      const double r = circle["radius"].get<double>();
      if (!(r > 0.0) || !std::isfinite(r)) return bad("the radius must be positive", cw);
      std::vector<Vector2> pts;
      for (int k = 0; k < kCircleSides; ++k) {
        const double a = 2.0 * kPi * k / kCircleSides;
        pts.push_back(centre + r * Vector2(std::cos(a), std::sin(a)));
      }
      c.polygons.push_back(std::move(pts));
    }
  }
  if (c.polygons.empty()) return bad("no polygon and no circle", where);
  if (j.contains("points")) {
    if (!j["points"].is_object()) return bad("\"points\" maps names to [x, z]", where);
    for (auto it = j["points"].begin(); it != j["points"].end(); ++it) {
      MOZZI_TRY_ASSIGN(auto v, point(it.value(), where + ", point " + it.key()));
      c.points.push_back({it.key(), v});
    }
  }
  if (j.contains("centre_of_gravity")) {
    MOZZI_TRY_ASSIGN(c.centreOfGravity, point(j["centre_of_gravity"], where + ", centre_of_gravity"));
    MOZZI_TRY_ASSIGN(c.centreOfGravityNote, text(j, "centre_of_gravity_note", where, false));
  }
  return c;
}

}  // namespace

const SilhouetteComponent::NamedPoint* SilhouetteComponent::point(const std::string& name) const {
  for (const auto& p : points)
    if (p.name == name) return &p;
  return nullptr;
}

const SilhouetteComponent* SilhouetteCatalogue::component(const std::string& key) const {
  for (const auto& c : components)
    if (c.key == key) return &c;
  return nullptr;
}

const SilhouettePlacement* SilhouetteCatalogue::placement(const std::string& specimenKey) const {
  for (const auto& p : placements)
    if (p.specimenKey == specimenKey) return &p;
  return nullptr;
}

Result<SilhouetteCatalogue> parseSilhouettes(const std::string& json) {
  const auto j = nlohmann::json::parse(json, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return bad("not a JSON object", "file");
  SilhouetteCatalogue cat;
  MOZZI_TRY_ASSIGN(cat.format, text(j, "format", "file"));
  if (cat.format != "mozzi-silhouettes 1") return bad("unknown format \"" + cat.format + "\"", "file");
  if (!j.contains("approximate") || !j["approximate"].is_boolean())
    return bad("\"approximate\" (true or false) is required", "file");
  cat.approximate = j["approximate"].get<bool>();
  MOZZI_TRY_ASSIGN(cat.note, text(j, "note", "file"));
  MOZZI_TRY_ASSIGN(cat.coordinates, text(j, "coordinates", "file"));
  if (!j.contains("components") || !j["components"].is_object()) return bad("\"components\" is required", "file");
  for (auto it = j["components"].begin(); it != j["components"].end(); ++it) {
    MOZZI_TRY_ASSIGN(auto c, component(it.key(), it.value()));
    cat.components.push_back(std::move(c));
  }
  if (!j.contains("specimens") || !j["specimens"].is_object()) return bad("\"specimens\" is required", "file");
  for (auto it = j["specimens"].begin(); it != j["specimens"].end(); ++it) {
    const std::string where = "specimen " + it.key();
    const auto& s = it.value();
    if (!s.is_object()) return bad("a specimen's placement is an object", where);
    SilhouettePlacement p;
    p.specimenKey = it.key();
    if (!s.contains("components") || !s["components"].is_array() || s["components"].empty())
      return bad("\"components\" lists the components drawn", where);
    for (const auto& c : s["components"]) {
      if (!c.is_string() || !cat.component(c.get<std::string>()))
        return bad("names a component the file does not have", where);
      p.components.push_back(c.get<std::string>());
    }
    MOZZI_TRY_ASSIGN(auto load, text(s, "load_point", where));
    MOZZI_TRY_ASSIGN(auto constrained, text(s, "constrained_end", where));
    const SilhouetteComponent* first = cat.component(p.components.front());
    if (!first->point(load)) return bad("load point \"" + load + "\" is not a point of " + first->key, where);
    if (!first->point(constrained))
      return bad("constrained end \"" + constrained + "\" is not a point of " + first->key, where);
    p.loadPoint = load;
    p.constrainedEnd = constrained;
    if (s.contains("u_sign")) {
      if (!s["u_sign"].is_number() || std::abs(std::abs(s["u_sign"].get<double>()) - 1.0) > 0.0)
        return bad("\"u_sign\" is 1 or -1", where);
      p.uSign = s["u_sign"].get<double>();
    }
    cat.placements.push_back(std::move(p));
  }
  return cat;
}

Result<PlacedSilhouette> placeSilhouette(const SilhouetteCatalogue& catalogue, const std::string& specimenKey,
                                         const Vector2& loadPoint) {
  const SilhouettePlacement* p = catalogue.placement(specimenKey);
  if (!p)
    return makeError(ErrorCode::NotFound, "no silhouette for this specimen", "silhouettes: specimen " + specimenKey);
  const SilhouetteComponent* first = catalogue.component(p->components.front());
  const Vector2 origin = first->point(p->loadPoint)->at;
  auto place = [&](const Vector2& x) {
    return Vector2(loadPoint(0) + p->uSign * (x(0) - origin(0)), loadPoint(1) + (x(1) - origin(1)));
  };
  PlacedSilhouette out;
  out.specimenKey = specimenKey;
  out.name = first->name;
  out.approximate = catalogue.approximate;
  for (const auto& key : p->components) {
    const SilhouetteComponent* c = catalogue.component(key);
    if (!out.source.empty()) out.source += "; ";
    out.source += c->source;
    for (const auto& poly : c->polygons) {
      std::vector<Vector2> placed;
      for (const auto& x : poly) placed.push_back(place(x));
      out.polygons.push_back(std::move(placed));
    }
  }
  out.loadPoint = loadPoint;
  out.loadPointName = p->loadPoint;
  out.constrainedEnd = place(first->point(p->constrainedEnd)->at);
  out.constrainedEndName = p->constrainedEnd;
  if (first->centreOfGravity) {
    out.centreOfGravity = place(*first->centreOfGravity);
    out.centreOfGravityNote = first->centreOfGravityNote;
  }
  return out;
}

}  // namespace mozzi::core::stiffness
