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
using sql::sqliteError;

// --- mesh -----------------------------------------------------------------------

Result<void> ProjectStore::setMesh(std::int64_t specimenId, const StoredMesh& mesh) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  MOZZI_TRY(requireWritable());
  const std::string where = path_ + ", mesh of specimen " + std::to_string(specimenId);
  for (const auto& n : mesh.nodes) {
    if (!n.position.allFinite()) {
      return makeError(ErrorCode::InvalidArgument, "node " + std::to_string(n.label) + " has a non-finite position",
                       where);
    }
  }
  sql::Transaction tx(db_, where);
  MOZZI_TRY(tx.begun());
  {
    sql::Statement exists(db_, "SELECT 1 FROM specimen WHERE id = ?1");
    exists.bind(1, specimenId);
    if (exists.step() != SQLITE_ROW) return makeError(ErrorCode::NotFound, "no such specimen", where);
  }
  for (const char* table : {"mesh_face", "mesh_line", "mesh_node", "coordinate_system"}) {
    sql::Statement del(db_, (std::string("DELETE FROM ") + table + " WHERE specimen_id = ?1").c_str());
    del.bind(1, specimenId);
    MOZZI_TRY(del.run(std::string("cannot clear ") + table, where));
  }
  sql::Statement cs(db_,
                    "INSERT INTO coordinate_system(specimen_id, label, name, kind, origin_x_m, origin_y_m, origin_z_m,"
                    " r11, r12, r13, r21, r22, r23, r31, r32, r33)"
                    " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16)");
  for (const auto& c : mesh.coordinateSystems) {
    cs.reset();
    cs.bind(1, specimenId).bind(2, c.label).bind(3, c.name).bind(4, static_cast<int>(c.kind));
    for (int i = 0; i < 3; ++i) cs.bind(5 + i, c.origin[i]);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) cs.bind(8 + 3 * i + j, c.rotation(i, j));
    }
    MOZZI_TRY(cs.run("cannot store coordinate system " + std::to_string(c.label), where));
  }
  std::map<int, std::int64_t> nodeIds;
  sql::Statement node(db_,
                      "INSERT INTO mesh_node(specimen_id, label, definition_cs, displacement_cs, x_m, y_m, z_m)"
                      " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
  for (const auto& n : mesh.nodes) {
    node.reset();
    node.bind(1, specimenId).bind(2, n.label).bind(3, n.definitionCs).bind(4, n.displacementCs);
    for (int i = 0; i < 3; ++i) node.bind(5 + i, n.position[i]);
    MOZZI_TRY(node.run("cannot store node " + std::to_string(n.label), where));
    nodeIds[n.label] = sqlite3_last_insert_rowid(db_);
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
    MOZZI_TRY_ASSIGN(auto a, idOf(l.nodeA, "a line"));
    MOZZI_TRY_ASSIGN(auto b, idOf(l.nodeB, "a line"));
    line.reset();
    line.bind(1, specimenId).bind(2, a).bind(3, b);
    MOZZI_TRY(line.run("cannot store a trace line", where));
  }
  sql::Statement face(db_,
                      "INSERT INTO mesh_face(specimen_id, node_a, node_b, node_c, node_d) VALUES (?1, ?2, ?3, ?4, ?5)");
  for (const auto& f : mesh.faces) {
    MOZZI_TRY_ASSIGN(auto a, idOf(f.nodeA, "a face"));
    MOZZI_TRY_ASSIGN(auto b, idOf(f.nodeB, "a face"));
    MOZZI_TRY_ASSIGN(auto c, idOf(f.nodeC, "a face"));
    std::optional<std::int64_t> d;
    if (f.nodeD != 0) {
      MOZZI_TRY_ASSIGN(auto dd, idOf(f.nodeD, "a face"));
      d = dd;
    }
    face.reset();
    face.bind(1, specimenId).bind(2, a).bind(3, b).bind(4, c).bind(5, d);
    MOZZI_TRY(face.run("cannot store a face", where));
  }
  sql::Statement crc(db_, "UPDATE specimen SET mesh_crc32 = ?1 WHERE id = ?2");
  crc.bind(1, static_cast<std::int64_t>(meshChecksum(mesh))).bind(2, specimenId);
  MOZZI_TRY(crc.run("cannot store the mesh checksum", where));
  return tx.commit();
}

namespace {

// Trace lines and faces of a mesh, by node label (mesh() has read the nodes).
Result<void> readMeshTopology(sqlite3* db, std::int64_t specimenId, StoredMesh& mesh, const std::string& where) {
  {
    sql::Statement stmt(db,
                        "SELECT a.label, b.label FROM mesh_line l JOIN mesh_node a ON a.id = l.node_a"
                        " JOIN mesh_node b ON b.id = l.node_b WHERE l.specimen_id = ?1 ORDER BY l.id");
    stmt.bind(1, specimenId);
    int rc;
    while ((rc = stmt.step()) == SQLITE_ROW) {
      mesh.lines.push_back({sqlite3_column_int(stmt.get(), 0), sqlite3_column_int(stmt.get(), 1)});
    }
    if (rc != SQLITE_DONE) return sqliteError(db, "cannot read trace lines", where);
  }
  {
    sql::Statement stmt(db,
                        "SELECT a.label, b.label, c.label, d.label FROM mesh_face f"
                        " JOIN mesh_node a ON a.id = f.node_a JOIN mesh_node b ON b.id = f.node_b"
                        " JOIN mesh_node c ON c.id = f.node_c LEFT JOIN mesh_node d ON d.id = f.node_d"
                        " WHERE f.specimen_id = ?1 ORDER BY f.id");
    stmt.bind(1, specimenId);
    int rc;
    while ((rc = stmt.step()) == SQLITE_ROW) {
      StoredFace f;
      f.nodeA = sqlite3_column_int(stmt.get(), 0);
      f.nodeB = sqlite3_column_int(stmt.get(), 1);
      f.nodeC = sqlite3_column_int(stmt.get(), 2);
      f.nodeD = sqlite3_column_type(stmt.get(), 3) == SQLITE_NULL ? 0 : sqlite3_column_int(stmt.get(), 3);
      mesh.faces.push_back(f);
    }
    if (rc != SQLITE_DONE) return sqliteError(db, "cannot read faces", where);
  }
  return {};
}

}  // namespace

Result<StoredMesh> ProjectStore::mesh(std::int64_t specimenId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", mesh of specimen " + std::to_string(specimenId);
  StoredMesh mesh;
  {
    sql::Statement stmt(
        db_,
        "SELECT id, label, name, kind, origin_x_m, origin_y_m, origin_z_m, r11, r12, r13, r21, r22, r23,"
        " r31, r32, r33 FROM coordinate_system WHERE specimen_id = ?1 ORDER BY label");
    stmt.bind(1, specimenId);
    int rc;
    while ((rc = stmt.step()) == SQLITE_ROW) {
      StoredCoordinateSystem c;
      c.id = sqlite3_column_int64(stmt.get(), 0);
      c.label = sqlite3_column_int(stmt.get(), 1);
      c.name = sql::columnText(stmt.get(), 2);
      const int kind = sqlite3_column_int(stmt.get(), 3);
      if (kind < 0 || kind > 2) return makeError(ErrorCode::Corrupt, "unknown coordinate-system kind", where);
      c.kind = static_cast<StoredCoordinateSystem::Kind>(kind);
      for (int i = 0; i < 3; ++i) c.origin[i] = sqlite3_column_double(stmt.get(), 4 + i);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) c.rotation(i, j) = sqlite3_column_double(stmt.get(), 7 + 3 * i + j);
      }
      mesh.coordinateSystems.push_back(c);
    }
    if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read coordinate systems", where);
  }
  {
    sql::Statement stmt(db_,
                        "SELECT id, label, definition_cs, displacement_cs, x_m, y_m, z_m FROM mesh_node"
                        " WHERE specimen_id = ?1 ORDER BY label");
    stmt.bind(1, specimenId);
    int rc;
    while ((rc = stmt.step()) == SQLITE_ROW) {
      StoredNode n;
      n.id = sqlite3_column_int64(stmt.get(), 0);
      n.label = sqlite3_column_int(stmt.get(), 1);
      n.definitionCs = sqlite3_column_int(stmt.get(), 2);
      n.displacementCs = sqlite3_column_int(stmt.get(), 3);
      for (int i = 0; i < 3; ++i) n.position[i] = sqlite3_column_double(stmt.get(), 4 + i);
      mesh.nodes.push_back(n);
    }
    if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read nodes", where);
  }
  MOZZI_TRY(readMeshTopology(db_, specimenId, mesh, where));
  sql::Statement crc(db_, ("SELECT " + crcColumn("mesh_crc32") + " FROM specimen WHERE id = ?1").c_str());
  crc.bind(1, specimenId);
  if (crc.step() == SQLITE_ROW) {
    MOZZI_TRY(verifyChecksum(crc.get(), 0, meshChecksum(mesh), "mesh", where));
  }
  return mesh;
}

// --- rig set-ups -------------------------------------------------------------------

Result<std::int64_t> ProjectStore::addRigSetup(const StoredRigSetup& setup) {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  MOZZI_TRY(requireWritable());
  const std::string where = path_ + ", rig set-up '" + setup.name + "'";
  if (setup.name.empty()) return makeError(ErrorCode::InvalidArgument, "a rig set-up needs a name", where);
  sql::Transaction tx(db_, where);
  MOZZI_TRY(tx.begun());
  sql::Statement stmt(db_,
                      "INSERT INTO rig_setup(specimen_id, name, rig_kind, driver, axis_map_json, parameters_json,"
                      " created_utc) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
  stmt.bind(1, setup.specimenId).bind(2, setup.name).bind(3, setup.rigKind).bind(4, setup.driver);
  stmt.bind(5, setup.axisMapJson).bind(6, setup.parametersJson).bind(7, sql::nowUtc());
  MOZZI_TRY_ASSIGN(const std::int64_t id, stmt.insert("cannot store the rig set-up", where));
  sql::Statement tr(db_,
                    "INSERT INTO transducer(rig_setup_id, channel, quantity, unit, sensitivity, model, serial,"
                    " dof_node, dof_direction) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9)");
  for (const auto& t : setup.transducers) {
    if (!(t.sensitivity > 0.0) || !finite(t.sensitivity)) {
      return makeError(ErrorCode::InvalidArgument,
                       "transducer on channel " + std::to_string(t.channel) + " needs a positive sensitivity", where);
    }
    tr.reset();
    tr.bind(1, id).bind(2, t.channel).bind(3, t.quantity).bind(4, t.unit).bind(5, t.sensitivity);
    tr.bind(6, t.model).bind(7, t.serial).bindDof(8, t.dof);
    MOZZI_TRY(tr.run("cannot store the transducer on channel " + std::to_string(t.channel), where));
  }
  MOZZI_TRY(tx.commit());
  return id;
}

Result<StoredRigSetup> ProjectStore::rigSetup(std::int64_t rigSetupId) const {
  const std::lock_guard<std::recursive_mutex> lock(*mutex_);
  const std::string where = path_ + ", rig set-up " + std::to_string(rigSetupId);
  StoredRigSetup s;
  {
    sql::Statement stmt(db_,
                        "SELECT id, specimen_id, name, rig_kind, driver, axis_map_json, parameters_json FROM rig_setup"
                        " WHERE id = ?1");
    stmt.bind(1, rigSetupId);
    MOZZI_TRY(stmt.single("cannot read the rig set-up", "no such rig set-up", where));
    s.id = sqlite3_column_int64(stmt.get(), 0);
    s.specimenId = sqlite3_column_int64(stmt.get(), 1);
    s.name = sql::columnText(stmt.get(), 2);
    s.rigKind = sql::columnText(stmt.get(), 3);
    s.driver = sql::columnText(stmt.get(), 4);
    s.axisMapJson = sql::columnText(stmt.get(), 5);
    s.parametersJson = sql::columnText(stmt.get(), 6);
  }
  sql::Statement stmt(db_,
                      "SELECT id, channel, quantity, unit, sensitivity, model, serial, dof_node, dof_direction"
                      " FROM transducer WHERE rig_setup_id = ?1 ORDER BY channel");
  stmt.bind(1, rigSetupId);
  int rc;
  while ((rc = stmt.step()) == SQLITE_ROW) {
    StoredTransducer t;
    t.id = sqlite3_column_int64(stmt.get(), 0);
    t.channel = sqlite3_column_int(stmt.get(), 1);
    t.quantity = sql::columnText(stmt.get(), 2);
    t.unit = sql::columnText(stmt.get(), 3);
    t.sensitivity = sqlite3_column_double(stmt.get(), 4);
    t.model = sql::columnText(stmt.get(), 5);
    t.serial = sql::columnText(stmt.get(), 6);
    t.dof = sql::columnOptionalDof(stmt.get(), 7, 8);
    s.transducers.push_back(std::move(t));
  }
  if (rc != SQLITE_DONE) return sqliteError(db_, "cannot read transducers", where);
  return s;
}

}  // namespace mozzi::core::io
