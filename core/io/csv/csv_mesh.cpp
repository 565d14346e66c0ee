// CSV exchange of measurement meshes (docs/formats/csv.md, "Meshes"): nodes,
// coordinate systems, trace lines and faces in sections of one file.

#include "core/io/csv/csv_exchange.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <ostream>
#include <sstream>

#include "core/io/csv/csv_internal.h"

namespace mozzi::core::io::csv {

using namespace detail;  // NOLINT(google-build-using-namespace): the exchange's private helpers

// --- measurement meshes ----------------------------------------------------------------------
namespace {

constexpr std::array<const char*, 6> kMeshSections = {
    "coordinate-systems", "nodes", "lines", "faces", "dofs", "slaves"};

// One section of a mesh file: its name, its text and the line before it.
struct MeshSection {
  std::string name;
  std::string_view text;
  int lineOffset = 0;
  int line = 0;  // line of the "# section = " comment (0: implicit nodes section)
};

Result<int> integerField(double v, const std::string& what, const std::string& source, int line, int column) {
  if (v != std::floor(v) || std::abs(v) > 2147483647.0) {
    return parseError(what + " must be a whole number", source, line, column);
  }
  return static_cast<int>(v);
}

// Column index per expected name (lower case, units checked by the caller).
struct MeshColumns {
  std::map<std::string, std::size_t> index;
  std::map<std::string, std::optional<std::string>> unit;
};

Result<MeshColumns> meshColumns(const Table& t, const std::vector<std::string>& required,
                                const std::vector<std::string>& optional, const std::string& section,
                                const std::string& source) {
  MeshColumns cols;
  for (std::size_t c = 0; c < t.titles.size(); ++c) {
    const Title title = splitTitle(t.titles[c]);
    std::string name = lower(title.name);
    if (section == "nodes" && (name == "label" || name == "id" || name == "node id")) name = "node";
    const bool known = std::find(required.begin(), required.end(), name) != required.end() ||
                       std::find(optional.begin(), optional.end(), name) != optional.end();
    if (!known) {
      return parseError("column title '" + t.titles[c] + "' is not a column of the " + section + " section", source,
                        t.headerLine, static_cast<int>(c + 1));
    }
    if (!cols.index.emplace(name, c).second) {
      return parseError("column '" + name + "' appears twice", source, t.headerLine, static_cast<int>(c + 1));
    }
    cols.unit[name] = title.unit;
  }
  for (const auto& r : required) {
    if (!cols.index.count(r))
      return parseError("no '" + r + "' column in the " + section + " section", source, t.headerLine);
  }
  return cols;
}

// Length factor to metres of a coordinate column: a length unit is required.
Result<double> lengthFactor(const MeshColumns& cols, const std::string& name, const Table& t,
                            const std::string& source) {
  const auto& unit = cols.unit.at(name);
  const int col = static_cast<int>(cols.index.at(name) + 1);
  if (!unit) return parseError("column '" + name + "' needs a length unit ([m] or [mm])", source, t.headerLine, col);
  auto u = siUnit(*unit);
  if (!u || u->quantity != "displacement") {
    return parseError("column '" + name + "' needs a length unit ([m] or [mm])", source, t.headerLine, col);
  }
  return u->factor;
}

Result<void> checkDimensionless(const MeshColumns& cols, const std::string& name, const Table& t,
                                const std::string& source) {
  const auto& unit = cols.unit.at(name);
  if (unit && !unit->empty() && *unit != "1") {
    return parseError("column '" + name + "' is a count or a code: its unit is [1]", source, t.headerLine,
                      static_cast<int>(cols.index.at(name) + 1));
  }
  return {};
}

}  // namespace

Result<void> writeMeshCsv(const MeshDocument& document, std::ostream& out) {
  const auto& mesh = document.mesh;
  if (mesh.nodes.empty()) return makeError(ErrorCode::InvalidArgument, "the mesh has no nodes", "CSV export");
  for (const auto& cs : mesh.coordinateSystems) {
    if (!cs.origin.allFinite() || !cs.rotation.allFinite()) {
      return makeError(ErrorCode::InvalidArgument,
                       "coordinate system " + std::to_string(cs.label) + " has a non-finite value", "CSV export");
    }
    if (cs.name.find_first_of("\r\n") != std::string::npos) {
      return makeError(ErrorCode::InvalidArgument,
                       "the name of coordinate system " + std::to_string(cs.label) + " has a line break", "CSV export");
    }
  }
  for (const auto& n : mesh.nodes) {
    if (!n.position.allFinite()) {
      return makeError(ErrorCode::InvalidArgument, "node " + std::to_string(n.label) + " has a non-finite coordinate",
                       "CSV export");
    }
  }
  out << kMagic << ", mesh\n";
  if (!mesh.coordinateSystems.empty()) {
    out << "# section = coordinate-systems\n";
    for (const auto& cs : mesh.coordinateSystems)
      if (!cs.name.empty()) out << "# name " << cs.label << " = " << cs.name << '\n';
    out << "cs [1],type [1],origin x [m],origin y [m],origin z [m],x axis x [1],x axis y [1],x axis z [1],"
           "y axis x [1],y axis y [1],y axis z [1],z axis x [1],z axis y [1],z axis z [1]\n";
    for (const auto& cs : mesh.coordinateSystems) {
      out << cs.label << ',' << static_cast<int>(cs.kind) << ',' << num(cs.origin.x()) << ',' << num(cs.origin.y())
          << ',' << num(cs.origin.z());
      for (int axis = 0; axis < 3; ++axis)
        for (int k = 0; k < 3; ++k) out << ',' << num(cs.rotation(k, axis));  // column = axis
      out << '\n';
    }
  }
  out << "# section = nodes\n# coordinates in the node's definition system; angles of cylindrical and spherical "
         "systems in degrees\nnode [1],cs [1],displacement cs [1],x [m],y [m],z [m]\n";
  for (const auto& n : mesh.nodes) {
    out << n.label << ',' << n.definitionCs << ',' << n.displacementCs << ',' << num(n.position.x()) << ','
        << num(n.position.y()) << ',' << num(n.position.z()) << '\n';
  }
  if (!mesh.lines.empty()) {
    out << "# section = lines\nnode a [1],node b [1]\n";
    for (const auto& l : mesh.lines) out << l.nodeA << ',' << l.nodeB << '\n';
  }
  if (!mesh.faces.empty()) {
    out << "# section = faces\n# node d = 0 for a triangle\nnode a [1],node b [1],node c [1],node d [1]\n";
    for (const auto& f : mesh.faces) out << f.nodeA << ',' << f.nodeB << ',' << f.nodeC << ',' << f.nodeD << '\n';
  }
  if (!document.measurementDofs.empty()) {
    out << "# section = dofs\n# direction: UFF code +/-1..6 = X, Y, Z, RX, RY, RZ\nnode [1],direction [1]\n";
    for (const auto& d : document.measurementDofs) out << d.node << ',' << d.uffCode() << '\n';
  }
  if (!document.slaves.empty()) {
    out << "# section = slaves\n# u(slave) = sum of weight x u(master), one row per master\n"
           "slave node [1],slave direction [1],master node [1],master direction [1],weight [1]\n";
    for (const auto& s : document.slaves) {
      for (const auto& [master, weight] : s.masters) {
        if (!std::isfinite(weight)) {
          return makeError(ErrorCode::InvalidArgument, "a weight of slave " + formatDof(s.slave) + " is not finite",
                           "CSV export");
        }
        out << s.slave.node << ',' << s.slave.uffCode() << ',' << master.node << ',' << master.uffCode() << ','
            << num(weight) << '\n';
      }
    }
  }
  return written(out);
}

namespace {

// An integer field of row r (a label, a code), with the error naming the
// column.
Result<int> intAt(const Table& t, std::size_t r, const MeshColumns& cols, const std::string& source,
                  const std::string& name) {
  const std::size_t c = cols.index.at(name);
  return integerField(t.rows[r][c], name, source, t.rowLines[r], static_cast<int>(c + 1));
}

// One function per section kind; each appends what its table holds.
Result<void> readSystemsSection(const Table& t, const std::string& source, const std::string& sectionName,
                                MeshDocument& doc, std::map<int, StoredCoordinateSystem::Kind>& systemKinds) {
  auto& mesh = doc.mesh;
  std::vector<std::string> required = {"cs", "type", "origin x", "origin y", "origin z"};
  for (const char* axis : {"x", "y", "z"})
    for (const char* k : {"x", "y", "z"}) required.push_back(std::string(axis) + " axis " + k);
  MOZZI_TRY_ASSIGN(auto cols, meshColumns(t, required, {}, sectionName, source));
  double factor[3];
  for (int k = 0; k < 3; ++k) {
    MOZZI_TRY_ASSIGN(auto f, lengthFactor(cols, std::string("origin ") + "xyz"[k], t, source));
    factor[k] = f;
  }
  for (const auto& name : {"cs", "type"}) MOZZI_TRY(checkDimensionless(cols, name, t, source));
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    StoredCoordinateSystem cs;
    MOZZI_TRY_ASSIGN(auto label, intAt(t, r, cols, source, "cs"));
    MOZZI_TRY_ASSIGN(auto type, intAt(t, r, cols, source, "type"));
    if (label <= 0) return parseError("coordinate system labels are positive", source, t.rowLines[r]);
    if (type < 0 || type > 2) {
      return parseError("type must be 0 (cartesian), 1 (cylindrical) or 2 (spherical)", source, t.rowLines[r],
                        static_cast<int>(cols.index.at("type") + 1));
    }
    cs.label = label;
    cs.kind = static_cast<StoredCoordinateSystem::Kind>(type);
    for (int k = 0; k < 3; ++k) cs.origin[k] = factor[k] * t.rows[r][cols.index.at(std::string("origin ") + "xyz"[k])];
    for (int axis = 0; axis < 3; ++axis)
      for (int k = 0; k < 3; ++k)
        cs.rotation(k, axis) = t.rows[r][cols.index.at(std::string(1, "xyz"[axis]) + " axis " + "xyz"[k])];
    if (auto it = t.keys.find("name " + std::to_string(cs.label)); it != t.keys.end()) cs.name = it->second;
    if (!systemKinds.emplace(cs.label, cs.kind).second) {
      return parseError("coordinate system " + std::to_string(cs.label) + " is defined twice", source, t.rowLines[r]);
    }
    mesh.coordinateSystems.push_back(std::move(cs));
  }
  return {};
}

Result<void> readNodesSection(const Table& t, const std::string& source, const std::string& sectionName,
                              MeshDocument& doc, const std::map<int, StoredCoordinateSystem::Kind>& systemKinds) {
  auto& mesh = doc.mesh;
  MOZZI_TRY_ASSIGN(auto cols, meshColumns(t, {"node", "x", "y", "z"}, {"cs", "displacement cs"}, sectionName, source));
  double factor[3];
  for (int k = 0; k < 3; ++k) {
    MOZZI_TRY_ASSIGN(auto f, lengthFactor(cols, std::string(1, "xyz"[k]), t, source));
    factor[k] = f;
  }
  for (const auto& name : {"node", "cs", "displacement cs"})
    if (cols.index.count(name)) MOZZI_TRY(checkDimensionless(cols, name, t, source));
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    StoredNode n;
    MOZZI_TRY_ASSIGN(auto label, intAt(t, r, cols, source, "node"));
    n.label = label;
    if (n.label <= 0) return parseError("node labels are positive", source, t.rowLines[r]);
    for (const auto& [name, field] : {std::pair<const char*, int*>{"cs", &n.definitionCs},
                                      std::pair<const char*, int*>{"displacement cs", &n.displacementCs}}) {
      if (!cols.index.count(name)) continue;
      MOZZI_TRY_ASSIGN(auto v, intAt(t, r, cols, source, name));
      if (v < 0) return parseError(std::string(name) + " must not be negative", source, t.rowLines[r]);
      *field = v;
    }
    for (int k = 0; k < 3; ++k) n.position[k] = t.rows[r][cols.index.at(std::string(1, "xyz"[k]))];
    // Lengths scale with the column unit; angles (degrees) of cylindrical
    // (theta) and spherical (theta, phi) systems do not.
    const auto kindIt = systemKinds.find(n.definitionCs);
    const auto kindOf = kindIt == systemKinds.end() ? StoredCoordinateSystem::Kind::Cartesian : kindIt->second;
    n.position[0] *= factor[0];
    if (kindOf == StoredCoordinateSystem::Kind::Cartesian) n.position[1] *= factor[1];
    if (kindOf != StoredCoordinateSystem::Kind::Spherical) n.position[2] *= factor[2];
    mesh.nodes.push_back(n);
  }
  return {};
}

// Trace lines ("lines") or faces ("faces").
Result<void> readLinksSection(const Table& t, const std::string& source, const std::string& sectionName,
                              MeshDocument& doc) {
  auto& mesh = doc.mesh;
  const bool lines = sectionName == "lines";
  std::vector<std::string> required = {"node a", "node b"};
  if (!lines) required.push_back("node c");
  MOZZI_TRY_ASSIGN(auto cols,
                   meshColumns(t, required, lines ? std::vector<std::string>{} : std::vector<std::string>{"node d"},
                               sectionName, source));
  for (const auto& [name, index] : cols.index) MOZZI_TRY(checkDimensionless(cols, name, t, source));
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    int v[4] = {0, 0, 0, 0};
    for (int k = 0; k < 4; ++k) {
      const std::string name = std::string("node ") + "abcd"[k];
      if (!cols.index.count(name)) continue;
      MOZZI_TRY_ASSIGN(auto x, intAt(t, r, cols, source, name));
      if (x < 0 || (x == 0 && k < 3)) {
        return parseError(name + " must be a node label (positive)", source, t.rowLines[r],
                          static_cast<int>(cols.index.at(name) + 1));
      }
      v[k] = x;
    }
    if (lines) {
      mesh.lines.push_back({v[0], v[1]});
    } else {
      mesh.faces.push_back({v[0], v[1], v[2], v[3]});
    }
  }
  return {};
}

Result<void> readDofsSection(const Table& t, const std::string& source, const std::string& sectionName,
                             MeshDocument& doc) {
  MOZZI_TRY_ASSIGN(auto cols, meshColumns(t, {"node", "direction"}, {}, sectionName, source));
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    MOZZI_TRY_ASSIGN(auto node, intAt(t, r, cols, source, "node"));
    MOZZI_TRY_ASSIGN(auto code, intAt(t, r, cols, source, "direction"));
    auto dof = dofFromUff(node, code);
    if (!dof) {
      return parseError("direction must be a UFF code +/-1..6", source, t.rowLines[r],
                        static_cast<int>(cols.index.at("direction") + 1));
    }
    doc.measurementDofs.push_back(*dof);
  }
  return {};
}

Result<void> readSlavesSection(const Table& t, const std::string& source, const std::string& sectionName,
                               MeshDocument& doc) {
  MOZZI_TRY_ASSIGN(auto cols,
                   meshColumns(t, {"slave node", "slave direction", "master node", "master direction", "weight"}, {},
                               sectionName, source));
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    Dof dofs[2];
    for (int k = 0; k < 2; ++k) {
      const std::string who = k == 0 ? "slave" : "master";
      MOZZI_TRY_ASSIGN(auto node, intAt(t, r, cols, source, who + " node"));
      MOZZI_TRY_ASSIGN(auto code, intAt(t, r, cols, source, who + " direction"));
      auto dof = dofFromUff(node, code);
      if (!dof) {
        return parseError(who + " direction must be a UFF code +/-1..6", source, t.rowLines[r],
                          static_cast<int>(cols.index.at(who + " direction") + 1));
      }
      dofs[k] = *dof;
    }
    const double weight = t.rows[r][cols.index.at("weight")];
    // Rows of one slave are consecutive in files Mozzi writes; any order is read.
    auto it =
        std::find_if(doc.slaves.begin(), doc.slaves.end(), [&](const SlavedDof& s) { return s.slave == dofs[0]; });
    if (it == doc.slaves.end()) {
      doc.slaves.push_back({dofs[0], {}});
      it = doc.slaves.end() - 1;
    }
    it->masters.push_back({dofs[1], weight});
  }
  return {};
}

}  // namespace

Result<MeshDocument> readMeshCsv(std::string_view text, const std::string& source) {
  // Split into sections at "# section = <name>" lines; text before the first
  // one (other than comments) is a nodes table (the common "node, x, y, z"
  // file of other programs).
  std::vector<MeshSection> sections;
  std::string kind;
  {
    MeshSection current{"nodes", {}, 0, 0};
    std::size_t sectionStart = 0;
    std::size_t pos = 0;
    int lineNo = 0;
    while (pos < text.size()) {
      std::size_t end = text.find('\n', pos);
      if (end == std::string_view::npos) end = text.size();
      const std::string trimmed = lower(trim(text.substr(pos, end - pos)));
      ++lineNo;
      if (trimmed.rfind(kMagic, 0) == 0) {
        const std::size_t comma = trimmed.find(',');
        if (comma != std::string::npos) kind = trim(std::string_view(trimmed).substr(comma + 1));
      }
      if (trimmed.rfind("# section", 0) == 0 && trimmed.find('=') != std::string::npos) {
        current.text = text.substr(sectionStart, pos - sectionStart);
        sections.push_back(current);
        const std::string name = trim(std::string_view(trimmed).substr(trimmed.find('=') + 1));
        if (std::find(kMeshSections.begin(), kMeshSections.end(), name) == kMeshSections.end()) {
          return parseError("unknown section '" + name + "' (coordinate-systems, nodes, lines, faces, dofs or slaves)",
                            source, lineNo);
        }
        current = MeshSection{name, {}, lineNo, lineNo};
        sectionStart = std::min(end + 1, text.size());
      }
      pos = end + 1;
    }
    current.text = text.substr(std::min(sectionStart, text.size()));
    sections.push_back(current);
  }
  if (!kind.empty() && kind != "mesh") return parseError("this is a '" + kind + "' file, not a mesh", source, 1);

  MeshDocument doc;
  auto& mesh = doc.mesh;
  std::map<std::string, int> seen;
  std::map<int, StoredCoordinateSystem::Kind> systemKinds;
  for (const auto& section : sections) {
    // The implicit leading section may hold only comments.
    const bool implicit = section.line == 0;
    if (implicit) {
      bool content = false;
      std::size_t pos = 0;
      while (pos < section.text.size() && !content) {
        std::size_t end = section.text.find('\n', pos);
        if (end == std::string_view::npos) end = section.text.size();
        const std::string t = trim(section.text.substr(pos, end - pos));
        // A UTF-8 byte-order mark alone is not content.
        content = !t.empty() && t[0] != '#' && t != "\xEF\xBB\xBF";
        pos = end + 1;
      }
      if (!content) continue;
    }
    if (seen.count(section.name)) {
      return parseError("section '" + section.name + "' appears twice", source, std::max(section.line, 1));
    }
    seen[section.name] = section.line;
    MOZZI_TRY_ASSIGN(auto parsed, parseTable(section.text, source, section.lineOffset));
    const Table& t = parsed;
    if (section.name == "coordinate-systems") {
      if (seen.count("nodes")) {
        return parseError("the coordinate-systems section must come before the nodes", source, section.line);
      }
      MOZZI_TRY(readSystemsSection(t, source, section.name, doc, systemKinds));
    } else if (section.name == "nodes") {
      MOZZI_TRY(readNodesSection(t, source, section.name, doc, systemKinds));
    } else if (section.name == "lines" || section.name == "faces") {
      MOZZI_TRY(readLinksSection(t, source, section.name, doc));
    } else if (section.name == "dofs") {
      MOZZI_TRY(readDofsSection(t, source, section.name, doc));
    } else if (section.name == "slaves") {
      MOZZI_TRY(readSlavesSection(t, source, section.name, doc));
    }
  }
  if (mesh.nodes.empty()) return parseError("no nodes (a nodes section or a node, x, y, z table)", source, 1);
  return doc;
}

}  // namespace mozzi::core::io::csv
