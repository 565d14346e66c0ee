// UFF geometry datasets: 15 / 2411 (nodes), 18 / 2420 (coordinate systems),
// 82 (trace lines); see uff_parse.h and the layouts at the top of uff_reader.cpp.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include <Eigen/Geometry>

#include "core/io/uff/uff_parse.h"

namespace mozzi::core::io::uff::parsing {

// --- 15 / 2411 ------------------------------------------------------------
namespace {
// Record 1 of a node or a coordinate system (label first) with fewer than
// `count` columns, as short lines of some writers have: the missing ones are
// 0, with a warning.
void padRecord1(DatasetContext& ctx, std::vector<long long>& values, std::size_t count, const char* what) {
  if (values.size() >= count) return;
  ctx.warn("record 1 of " + std::string(what) + " " + std::to_string(values[0]) + ": " + std::to_string(values.size()) +
           " of " + std::to_string(count) + " columns; the missing ones are 0");
  values.resize(count, 0);
}
}  // namespace

Result<DatasetData> parseNodes(DatasetContext& ctx, int type) {
  NodeSet set;
  set.datasetType = type;
  for (;;) {
    std::string_view line;
    const Line l = ctx.nextNonBlank(line);
    if (l == Line::Delimiter) break;
    if (l == Line::Eof) return ctx.endedBefore("the closing -1 of the node list");
    Node n;
    if (type == 15) {
      // (4I10,1P3E13.5) on one line
      double v[7];
      std::size_t have = 0;
      const auto r = scanNumbers(line, [&](double x) {
        if (have >= 7) return false;
        v[have++] = x;
        return true;
      });
      if (r.status != NumberStatus::Ok || r.stopped || have != 7) {
        return ctx.error("node record: expected 4 integers and 3 coordinates, found '" + detail::excerpt(line) + "'");
      }
      for (int i = 0; i < 4; ++i) {
        if (v[i] != std::floor(v[i]) || std::abs(v[i]) > 2147483647.0) {
          return ctx.error("node record: '" + detail::excerpt(line) + "' has a non-integer label or system");
        }
      }
      n.label = static_cast<int>(v[0]);
      n.definitionCs = static_cast<int>(v[1]);
      n.displacementCs = static_cast<int>(v[2]);
      n.color = static_cast<int>(v[3]);
      n.xyz = Vector3(v[4], v[5], v[6]);
    } else {
      // (4I10) then (1P3D25.16)
      std::vector<long long> ints;
      detail::Words words(line);
      for (std::string_view w; words.next(w);) {
        long long x = 0;
        if (!parseInt(w, x) || !fitsInt(x) || ints.size() == 4) {
          return ctx.error("record 1 of a node: expected 4 integers, found '" + detail::excerpt(line) + "'");
        }
        ints.push_back(x);
      }
      if (ints.empty()) return ctx.error("record 1 of a node: no node label");
      padRecord1(ctx, ints, 4, "node");
      n.label = static_cast<int>(ints[0]);
      n.definitionCs = static_cast<int>(ints[1]);
      n.displacementCs = static_cast<int>(ints[2]);
      n.color = static_cast<int>(ints[3]);
      double xyz[3];
      MOZZI_TRY(readNumbers(ctx, 3, xyz, "record 2 (coordinates) of node " + std::to_string(n.label)));
      n.xyz = Vector3(xyz[0], xyz[1], xyz[2]);
    }
    set.nodes.push_back(n);
  }
  return DatasetData{std::move(set)};
}

// --- 18 / 2420 --------------------------------------------------------------
// Unit axes from origin, a point on +x and a point in the +xz plane:
// x = (P_x - O)/|P_x - O|, y = ((P_xz - O) x x)/|...|, z = x x y.
namespace {
bool axesFromPoints(CoordinateSystem& cs) {
  const Vector3 ex = cs.xPoint - cs.origin;
  const Vector3 exz = cs.xzPoint - cs.origin;
  const Vector3 ey = exz.cross(ex);
  if (ex.norm() == 0.0 || ey.norm() <= 1e-12 * ex.norm() * exz.norm()) return false;
  const Vector3 x = ex.normalized();
  const Vector3 y = ey.normalized();
  cs.axes.row(0) = x.transpose();
  cs.axes.row(1) = y.transpose();
  cs.axes.row(2) = x.cross(y).transpose();
  return true;
}
}  // namespace

Result<DatasetData> parse18(DatasetContext& ctx) {
  CoordinateSystemSet set;
  set.datasetType = 18;
  for (;;) {
    std::string_view line;
    const Line l = ctx.nextNonBlank(line);
    if (l == Line::Delimiter) break;
    if (l == Line::Eof) return ctx.endedBefore("the closing -1 of the coordinate systems");
    CoordinateSystem cs;
    const auto head = [&]() -> Result<std::vector<long long>> {
      std::vector<long long> v;
      const auto r = scanNumbers(line, [&](double x) {
        if (v.size() >= 5 || x != std::floor(x) || std::abs(x) > 2147483647.0) return false;
        v.push_back(static_cast<long long>(x));
        return true;
      });
      if (r.status != NumberStatus::Ok || r.stopped || v.empty()) {
        return ctx.error("record 1: expected 5 integers (label, type, reference, color, method), found '" +
                         detail::excerpt(line) + "'");
      }
      return v;
    }();
    if (!head) return head.error();
    std::vector<long long> h = *head;
    padRecord1(ctx, h, 5, "coordinate system");
    cs.label = static_cast<int>(h[0]);
    cs.type = static_cast<int>(h[1]);
    cs.referenceCs = static_cast<int>(h[2]);
    cs.color = static_cast<int>(h[3]);
    cs.definitionMethod = static_cast<int>(h[4]);
    std::string_view name;
    if (ctx.next(name) != Line::Ok)
      return ctx.endedBefore("record 2 (name) of coordinate system " + std::to_string(cs.label));
    cs.name = textField(name);
    double p[9];
    MOZZI_TRY(readNumbers(ctx, 9, p, "records 3-4 (points) of coordinate system " + std::to_string(cs.label)));
    cs.origin = Vector3(p[0], p[1], p[2]);
    cs.xPoint = Vector3(p[3], p[4], p[5]);
    cs.xzPoint = Vector3(p[6], p[7], p[8]);
    if (!axesFromPoints(cs)) {
      ctx.warn("coordinate system " + std::to_string(cs.label) +
               ": origin, +x point and +xz point are collinear; axes left as identity");
      cs.axes = Matrix3::Identity();
    }
    set.systems.push_back(std::move(cs));
  }
  return DatasetData{std::move(set)};
}

Result<DatasetData> parse2420(DatasetContext& ctx) {
  CoordinateSystemSet set;
  set.datasetType = 2420;
  MOZZI_TRY_ASSIGN(auto uid, readIntLine(ctx, 1, 1, "record 1 (part UID)"));
  set.partUid = static_cast<int>(std::clamp<long long>(uid[0], -2147483647, 2147483647));
  std::string_view partName;
  if (ctx.next(partName) != Line::Ok) return ctx.endedBefore("record 2 (part name)");
  set.partName = textField(partName);
  for (;;) {
    std::string_view line;
    const Line l = ctx.nextNonBlank(line);
    if (l == Line::Delimiter) break;
    if (l == Line::Eof) return ctx.endedBefore("the closing -1 of the coordinate systems");
    std::vector<long long> h;
    const auto r = scanNumbers(line, [&](double x) {
      if (h.size() >= 3 || x != std::floor(x) || std::abs(x) > 2147483647.0) return false;
      h.push_back(static_cast<long long>(x));
      return true;
    });
    if (r.status != NumberStatus::Ok || r.stopped || h.size() != 3) {
      return ctx.error("record 3: expected 3 integers (label, type, color), found '" + detail::excerpt(line) + "'");
    }
    CoordinateSystem cs;
    cs.label = static_cast<int>(h[0]);
    cs.type = static_cast<int>(h[1]);
    cs.color = static_cast<int>(h[2]);
    std::string_view name;
    if (ctx.next(name) != Line::Ok)
      return ctx.endedBefore("record 4 (name) of coordinate system " + std::to_string(cs.label));
    cs.name = textField(name);
    double m[12];
    if (auto rr =
            readNumbers(ctx, 12, m, "records 5-8 (transformation) of coordinate system " + std::to_string(cs.label));
        !rr) {
      return rr.error();
    }
    for (int i = 0; i < 3; ++i) cs.axes.row(i) = Eigen::RowVector3d(m[3 * i], m[3 * i + 1], m[3 * i + 2]);
    cs.origin = Vector3(m[9], m[10], m[11]);
    cs.xPoint = cs.origin + cs.axes.row(0).transpose();
    cs.xzPoint = cs.origin + cs.axes.row(2).transpose();
    set.systems.push_back(std::move(cs));
  }
  return DatasetData{std::move(set)};
}

// --- 82 ----------------------------------------------------------------------
Result<DatasetData> parse82(DatasetContext& ctx) {
  TraceLine82 t;
  MOZZI_TRY_ASSIGN(const std::vector<long long> h,
                   readIntLine(ctx, 2, 3, "record 1 (trace number, node count, color)"));
  if (h.size() < 3) ctx.warn("record 1: color column missing; 0 assumed");
  if (!fitsInt(h[0])) return ctx.error("record 1: trace number out of range");
  t.traceNumber = static_cast<int>(h[0]);
  t.color = h.size() > 2 && fitsInt(h[2]) ? static_cast<int>(h[2]) : 0;
  // The format caps a trace line at 250 nodes; more than a million is not a
  // trace line but a corrupt count.
  if (h[1] < 0 || h[1] > 1000000) {
    return ctx.error("record 1: node count " + std::to_string(h[1]) + " is not between 0 and 1000000");
  }
  const std::size_t count = static_cast<std::size_t>(h[1]);
  std::string desc;
  if (textLine(ctx, desc) != Line::Ok) return ctx.endedBefore("record 2 (description)");
  t.description = desc;
  t.nodes.reserve(count);
  std::size_t padding = 0;
  std::size_t extra = 0;
  for (;;) {
    std::string_view line;
    const Line l = ctx.next(line);
    if (l == Line::Delimiter) break;
    if (l == Line::Eof) {
      if (t.nodes.size() < count) return ctx.endedBefore("all " + std::to_string(count) + " trace nodes");
      ctx.warn("file ends without the closing -1");
      break;
    }
    detail::Words words(line);
    for (std::string_view w; words.next(w);) {
      long long v = 0;
      if (!parseInt(w, v) || !fitsInt(v)) {
        return ctx.error("record 3: '" + detail::excerpt(w) + "' is not a node number");
      }
      if (t.nodes.size() < count) {
        t.nodes.push_back(static_cast<int>(v));
      } else if (v == 0) {
        ++padding;  // TestLab pads the node list with zeros to a multiple of 8
      } else {
        ++extra;
      }
    }
  }
  if (extra > 0)
    ctx.warn(std::to_string(extra) + " node numbers after the " + std::to_string(count) + " declared were ignored");
  if (t.nodes.size() < count) {
    ctx.warn("record 1 declares " + std::to_string(count) + " nodes, the list holds " + std::to_string(t.nodes.size()));
  }
  return DatasetData{std::move(t)};
}

}  // namespace mozzi::core::io::uff::parsing
