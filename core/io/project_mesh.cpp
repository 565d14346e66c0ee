// ProjectStore: the mesh of a specimen (coordinate systems, nodes, trace lines,
// faces) and the rig set-ups with their transducers.

#include <map>
#include <utility>

#include "core/io/project_data_internal.h"
#include "core/io/project_sql.h"
#include "core/io/project_store.h"

namespace mozzi::core::io {

using data::finite;
using data::meshChecksum;
using data::verifyChecksum;

// --- mesh -----------------------------------------------------------------------

Result<void> ProjectStore::setMesh(std::int64_t specimenId, const StoredMesh& mesh) {
  const std::string where = path_ + ", mesh of specimen " + std::to_string(specimenId);
  return writeInTransaction(where, [&] { return insertMesh(specimenId, mesh, where); });
}

Result<void> ProjectStore::insertMesh(std::int64_t specimenId, const StoredMesh& mesh, const std::string& where) {
  for (const auto& n : mesh.nodes) {
    if (!n.position.allFinite()) {
      return makeError(ErrorCode::InvalidArgument, "node " + std::to_string(n.label) + " has a non-finite position",
                       where);
    }
  }
  sql::Statement exists(db_, "SELECT 1 FROM specimen WHERE id = ?1");
  if (exists.bindAll(specimenId).step() != SQLITE_ROW) return makeError(ErrorCode::NotFound, "no such specimen", where);
  for (const char* table : {"mesh_face", "mesh_line", "mesh_node", "coordinate_system"}) {
    sql::Statement del(db_, std::string("DELETE FROM ") + table + " WHERE specimen_id = ?1");
    MOZZI_TRY(del.bindAll(specimenId).run(std::string("cannot clear ") + table, where));
  }
  sql::Statement cs(db_,
                    "INSERT INTO coordinate_system(specimen_id, label, name, kind, origin_x_m, origin_y_m, origin_z_m,"
                    " r11, r12, r13, r21, r22, r23, r31, r32, r33)"
                    " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16)");
  for (const auto& c : mesh.coordinateSystems) {
    const Matrix3& r = c.rotation;
    MOZZI_TRY(cs.runWith("cannot store coordinate system " + std::to_string(c.label), where, specimenId, c.label,
                         c.name, static_cast<int>(c.kind), c.origin[0], c.origin[1], c.origin[2], r(0, 0), r(0, 1),
                         r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1), r(2, 2)));
  }
  std::map<int, std::int64_t> nodeIds;
  sql::Statement node(db_,
                      "INSERT INTO mesh_node(specimen_id, label, definition_cs, displacement_cs, x_m, y_m, z_m)"
                      " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
  for (const auto& n : mesh.nodes) {
    MOZZI_TRY_ASSIGN(nodeIds[n.label],
                     node.insertWith("cannot store node " + std::to_string(n.label), where, specimenId, n.label,
                                     n.definitionCs, n.displacementCs, n.position[0], n.position[1], n.position[2]));
  }
  auto idOf = [&](int label, const char* what) -> Result<std::int64_t> {
    auto it = nodeIds.find(label);
    if (it == nodeIds.end()) {
      return makeError(ErrorCode::InvalidArgument,
                       std::string(what) + " names node " + std::to_string(label) + ", which is not in the mesh",
                       where);
    }
    return it->second;
  };
  sql::Statement line(db_, "INSERT INTO mesh_line(specimen_id, node_a, node_b) VALUES (?1, ?2, ?3)");
  for (const auto& l : mesh.lines) {
    MOZZI_TRY_ASSIGN(const auto a, idOf(l.nodeA, "a line"));
    MOZZI_TRY_ASSIGN(const auto b, idOf(l.nodeB, "a line"));
    MOZZI_TRY(line.runWith("cannot store a trace line", where, specimenId, a, b));
  }
  sql::Statement face(db_,
                      "INSERT INTO mesh_face(specimen_id, node_a, node_b, node_c, node_d) VALUES (?1, ?2, ?3, ?4, ?5)");
  for (const auto& f : mesh.faces) {
    MOZZI_TRY_ASSIGN(const auto a, idOf(f.nodeA, "a face"));
    MOZZI_TRY_ASSIGN(const auto b, idOf(f.nodeB, "a face"));
    MOZZI_TRY_ASSIGN(const auto c, idOf(f.nodeC, "a face"));
    std::optional<std::int64_t> d;
    if (f.nodeD != 0) {
      MOZZI_TRY_ASSIGN(d, idOf(f.nodeD, "a face"));
    }
    MOZZI_TRY(face.runWith("cannot store a face", where, specimenId, a, b, c, d));
  }
  sql::Statement crc(db_, "UPDATE specimen SET mesh_crc32 = ?1 WHERE id = ?2");
  return crc.bindAll(meshChecksum(mesh), specimenId).run("cannot store the mesh checksum", where);
}

namespace {

// Trace lines and faces of a mesh, by node label (mesh() has read the nodes).
Result<void> readMeshTopology(sqlite3* db, std::int64_t specimenId, StoredMesh& mesh, const std::string& where) {
  sql::Statement lines(db,
                       "SELECT a.label, b.label FROM mesh_line l JOIN mesh_node a ON a.id = l.node_a"
                       " JOIN mesh_node b ON b.id = l.node_b WHERE l.specimen_id = ?1 ORDER BY l.id");
  MOZZI_TRY(lines.bindAll(specimenId).forEachRow("cannot read trace lines", where, [&](const sql::Row& r) {
    mesh.lines.push_back({r.int32(0), r.int32(1)});
  }));
  sql::Statement faces(db,
                       "SELECT a.label, b.label, c.label, d.label FROM mesh_face f"
                       " JOIN mesh_node a ON a.id = f.node_a JOIN mesh_node b ON b.id = f.node_b"
                       " JOIN mesh_node c ON c.id = f.node_c LEFT JOIN mesh_node d ON d.id = f.node_d"
                       " WHERE f.specimen_id = ?1 ORDER BY f.id");
  return faces.bindAll(specimenId).forEachRow("cannot read faces", where, [&](const sql::Row& r) {
    // A triangle's fourth node is NULL, read as 0.
    mesh.faces.push_back({r.int32(0), r.int32(1), r.int32(2), r.int32(3)});
  });
}

}  // namespace

Result<StoredMesh> ProjectStore::mesh(std::int64_t specimenId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", mesh of specimen " + std::to_string(specimenId);
  StoredMesh mesh;
  sql::Statement systems(db_,
                         "SELECT id, label, name, kind, origin_x_m, origin_y_m, origin_z_m, r11, r12, r13, r21, r22,"
                         " r23, r31, r32, r33 FROM coordinate_system WHERE specimen_id = ?1 ORDER BY label");
  MOZZI_TRY(systems.bindAll(specimenId)
                .forEachRow("cannot read coordinate systems", where, [&](const sql::Row& r) -> Result<void> {
                  StoredCoordinateSystem c;
                  c.id = r.int64(0);
                  c.label = r.int32(1);
                  c.name = r.text(2);
                  const int kind = r.int32(3);
                  if (kind < 0 || kind > 2)
                    return makeError(ErrorCode::Corrupt, "unknown coordinate-system kind", where);
                  c.kind = static_cast<StoredCoordinateSystem::Kind>(kind);
                  c.origin = Vector3(r.real(4), r.real(5), r.real(6));
                  for (int k = 0; k < 9; ++k) c.rotation(k / 3, k % 3) = r.real(7 + k);  // row-major r11..r33
                  mesh.coordinateSystems.push_back(c);
                  return {};
                }));
  sql::Statement nodes(db_,
                       "SELECT id, label, definition_cs, displacement_cs, x_m, y_m, z_m FROM mesh_node"
                       " WHERE specimen_id = ?1 ORDER BY label");
  MOZZI_TRY(nodes.bindAll(specimenId).forEachRow("cannot read nodes", where, [&](const sql::Row& r) {
    mesh.nodes.push_back({r.int64(0), r.int32(1), r.int32(2), r.int32(3), Vector3(r.real(4), r.real(5), r.real(6))});
  }));
  MOZZI_TRY(readMeshTopology(db_, specimenId, mesh, where));
  sql::Statement crc(db_, "SELECT " + crcColumn("mesh_crc32") + " FROM specimen WHERE id = ?1");
  if (crc.bindAll(specimenId).step() == SQLITE_ROW) {
    MOZZI_TRY(verifyChecksum(crc.get(), 0, meshChecksum(mesh), "mesh", where));
  }
  return mesh;
}

// --- rig set-ups -------------------------------------------------------------------

Result<std::int64_t> ProjectStore::addRigSetup(const StoredRigSetup& setup) {
  const std::string where = path_ + ", rig set-up '" + setup.name + "'";
  return insertInTransaction(where, [&]() -> Result<std::int64_t> {
    if (setup.name.empty()) return makeError(ErrorCode::InvalidArgument, "a rig set-up needs a name", where);
    sql::Statement stmt(db_,
                        "INSERT INTO rig_setup(specimen_id, name, rig_kind, driver, axis_map_json, parameters_json,"
                        " created_utc) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
    stmt.bindAll(setup.specimenId, setup.name, setup.rigKind, setup.driver, setup.axisMapJson, setup.parametersJson,
                 sql::nowUtc());
    MOZZI_TRY_ASSIGN(const std::int64_t id, stmt.insert("cannot store the rig set-up", where));
    sql::Statement tr(db_,
                      "INSERT INTO transducer(rig_setup_id, channel, quantity, unit, sensitivity, model, serial,"
                      " dof_node, dof_direction) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9)");
    for (const auto& t : setup.transducers) {
      if (!(t.sensitivity > 0.0) || !finite(t.sensitivity)) {
        return makeError(ErrorCode::InvalidArgument,
                         "transducer on channel " + std::to_string(t.channel) + " needs a positive sensitivity", where);
      }
      MOZZI_TRY(tr.runWith("cannot store the transducer on channel " + std::to_string(t.channel), where, id, t.channel,
                           t.quantity, t.unit, t.sensitivity, t.model, t.serial, t.dof));
    }
    return id;
  });
}

Result<StoredRigSetup> ProjectStore::rigSetup(std::int64_t rigSetupId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", rig set-up " + std::to_string(rigSetupId);
  sql::Statement head(db_,
                      "SELECT id, specimen_id, name, rig_kind, driver, axis_map_json, parameters_json FROM rig_setup"
                      " WHERE id = ?1");
  MOZZI_TRY(head.lookup(rigSetupId, "rig set-up", where));
  const sql::Row h(head.get());
  StoredRigSetup s{h.int64(0), h.int64(1), h.text(2), h.text(3), h.text(4), h.text(5), h.text(6), {}};
  sql::Statement stmt(db_,
                      "SELECT id, channel, quantity, unit, sensitivity, model, serial, dof_node, dof_direction"
                      " FROM transducer WHERE rig_setup_id = ?1 ORDER BY channel");
  MOZZI_TRY(stmt.bindAll(rigSetupId).forEachRow("cannot read transducers", where, [&](const sql::Row& r) {
    s.transducers.push_back(
        {r.int64(0), r.int32(1), r.text(2), r.text(3), r.real(4), r.text(5), r.text(6), r.optionalDof(7, 8)});
  }));
  return s;
}

}  // namespace mozzi::core::io
