#include "core/io/project_schema.h"

namespace mozzi::core::io {
namespace {

// Schema 1. Conventions:
// - STRICT tables, INTEGER PRIMARY KEY row ids, SI units named in the column.
// - A DOF is two columns: node label and signed UFF direction code (+/-1..6).
// - Owned rows cascade with their owner (a specimen owns its mesh, set-ups,
//   campaigns, ...; a campaign owns its hits). A reference to something the
//   row does not own is SET NULL when the referent goes (a campaign survives
//   the deletion of its rig set-up) unless the row is meaningless without it
//   (an FRF belongs to its set; a finding to its analysis: CASCADE).
// - Time data blobs: float32 little endian, column-major (all samples of
//   channel 0, then channel 1, ...). encoding 0 = raw bytes, 1 = the bytes
//   shuffled into four byte planes then zlib-deflated (see sample_codec.h).
//   samples_crc32 is the CRC-32 of the raw bytes and is checked on every read.
const char* const kSchema1 = R"sql(
CREATE TABLE meta (
  key   TEXT PRIMARY KEY NOT NULL,
  value TEXT NOT NULL
) STRICT;

CREATE TABLE specimen (
  id          INTEGER PRIMARY KEY,
  name        TEXT NOT NULL UNIQUE,
  kind        TEXT NOT NULL,
  description TEXT NOT NULL DEFAULT ''
) STRICT;

-- Mesh: UFF 2420 coordinate systems, 2411 nodes, 82 trace lines, faces.
CREATE TABLE coordinate_system (
  id          INTEGER PRIMARY KEY,
  specimen_id INTEGER NOT NULL REFERENCES specimen(id) ON DELETE CASCADE,
  label       INTEGER NOT NULL CHECK (label > 0),
  name        TEXT NOT NULL DEFAULT '',
  kind        INTEGER NOT NULL DEFAULT 0 CHECK (kind IN (0, 1, 2)),  -- cartesian, cylindrical, spherical
  origin_x_m  REAL NOT NULL, origin_y_m REAL NOT NULL, origin_z_m REAL NOT NULL,
  -- rotation R (x_global = origin + R x_local), row-major
  r11 REAL NOT NULL, r12 REAL NOT NULL, r13 REAL NOT NULL,
  r21 REAL NOT NULL, r22 REAL NOT NULL, r23 REAL NOT NULL,
  r31 REAL NOT NULL, r32 REAL NOT NULL, r33 REAL NOT NULL,
  UNIQUE (specimen_id, label)
) STRICT;

CREATE TABLE mesh_node (
  id              INTEGER PRIMARY KEY,
  specimen_id     INTEGER NOT NULL REFERENCES specimen(id) ON DELETE CASCADE,
  label           INTEGER NOT NULL CHECK (label > 0),
  definition_cs   INTEGER NOT NULL DEFAULT 0 CHECK (definition_cs >= 0),    -- coordinate_system.label, 0 global
  displacement_cs INTEGER NOT NULL DEFAULT 0 CHECK (displacement_cs >= 0),
  x_m REAL NOT NULL, y_m REAL NOT NULL, z_m REAL NOT NULL,
  UNIQUE (specimen_id, label)
) STRICT;

CREATE TABLE mesh_line (
  id          INTEGER PRIMARY KEY,
  specimen_id INTEGER NOT NULL REFERENCES specimen(id) ON DELETE CASCADE,
  node_a      INTEGER NOT NULL REFERENCES mesh_node(id) ON DELETE CASCADE,
  node_b      INTEGER NOT NULL REFERENCES mesh_node(id) ON DELETE CASCADE,
  CHECK (node_a <> node_b)
) STRICT;
CREATE INDEX mesh_line_specimen ON mesh_line(specimen_id);
CREATE INDEX mesh_line_a ON mesh_line(node_a);
CREATE INDEX mesh_line_b ON mesh_line(node_b);

CREATE TABLE mesh_face (
  id          INTEGER PRIMARY KEY,
  specimen_id INTEGER NOT NULL REFERENCES specimen(id) ON DELETE CASCADE,
  node_a      INTEGER NOT NULL REFERENCES mesh_node(id) ON DELETE CASCADE,
  node_b      INTEGER NOT NULL REFERENCES mesh_node(id) ON DELETE CASCADE,
  node_c      INTEGER NOT NULL REFERENCES mesh_node(id) ON DELETE CASCADE,
  node_d      INTEGER REFERENCES mesh_node(id) ON DELETE CASCADE  -- NULL for a triangle
) STRICT;
CREATE INDEX mesh_face_specimen ON mesh_face(specimen_id);
CREATE INDEX mesh_face_a ON mesh_face(node_a);
CREATE INDEX mesh_face_b ON mesh_face(node_b);
CREATE INDEX mesh_face_c ON mesh_face(node_c);
CREATE INDEX mesh_face_d ON mesh_face(node_d);

-- Rig set-up and its transducers.
CREATE TABLE rig_setup (
  id              INTEGER PRIMARY KEY,
  specimen_id     INTEGER NOT NULL REFERENCES specimen(id) ON DELETE CASCADE,
  name            TEXT NOT NULL,
  rig_kind        TEXT NOT NULL,
  driver          TEXT NOT NULL DEFAULT '',
  axis_map_json   TEXT NOT NULL DEFAULT '{}',
  parameters_json TEXT NOT NULL DEFAULT '{}',
  created_utc     TEXT NOT NULL,
  UNIQUE (specimen_id, name)
) STRICT;

CREATE TABLE transducer (
  id            INTEGER PRIMARY KEY,
  rig_setup_id  INTEGER NOT NULL REFERENCES rig_setup(id) ON DELETE CASCADE,
  channel       INTEGER NOT NULL CHECK (channel >= 0),
  quantity      TEXT NOT NULL,
  unit          TEXT NOT NULL,
  sensitivity   REAL NOT NULL CHECK (sensitivity > 0),  -- [V per SI unit]
  model         TEXT NOT NULL DEFAULT '',
  serial        TEXT NOT NULL DEFAULT '',
  dof_node      INTEGER,
  dof_direction INTEGER CHECK (dof_direction BETWEEN -6 AND 6 AND dof_direction <> 0),
  CHECK ((dof_node IS NULL) = (dof_direction IS NULL)),
  UNIQUE (rig_setup_id, channel)
) STRICT;

-- Impact campaigns and every hit, accepted or rejected, with its raw data.
CREATE TABLE campaign (
  id           INTEGER PRIMARY KEY,
  specimen_id  INTEGER NOT NULL REFERENCES specimen(id) ON DELETE CASCADE,
  rig_setup_id INTEGER REFERENCES rig_setup(id) ON DELETE SET NULL,
  name         TEXT NOT NULL,
  kind         TEXT NOT NULL CHECK (kind IN ('roving-hammer', 'roving-accelerometer', 'shaker', 'other')),
  started_utc  TEXT NOT NULL,
  notes        TEXT NOT NULL DEFAULT '',
  UNIQUE (specimen_id, name)
) STRICT;
CREATE INDEX campaign_rig_setup ON campaign(rig_setup_id);

CREATE TABLE hit (
  id              INTEGER PRIMARY KEY,
  campaign_id     INTEGER NOT NULL REFERENCES campaign(id) ON DELETE CASCADE,
  sequence        INTEGER NOT NULL CHECK (sequence > 0),
  point_node      INTEGER NOT NULL,
  point_direction INTEGER NOT NULL CHECK (point_direction BETWEEN -6 AND 6 AND point_direction <> 0),
  recorded_utc    TEXT NOT NULL,
  sample_rate_hz  REAL NOT NULL CHECK (sample_rate_hz > 0),
  channel_count   INTEGER NOT NULL CHECK (channel_count > 0),
  sample_count    INTEGER NOT NULL CHECK (sample_count > 0),
  encoding        INTEGER NOT NULL CHECK (encoding IN (0, 1)),
  samples         BLOB NOT NULL,
  samples_crc32   INTEGER NOT NULL,
  accepted        INTEGER NOT NULL CHECK (accepted IN (0, 1)),
  quality_flags   INTEGER NOT NULL DEFAULT 0 CHECK (quality_flags >= 0),
  quality_reasons TEXT NOT NULL DEFAULT '',
  UNIQUE (campaign_id, sequence)
) STRICT;

CREATE TABLE hit_channel (
  hit_id        INTEGER NOT NULL REFERENCES hit(id) ON DELETE CASCADE,
  channel       INTEGER NOT NULL CHECK (channel >= 0),
  quantity      TEXT NOT NULL DEFAULT '',
  unit          TEXT NOT NULL DEFAULT '',
  dof_node      INTEGER,
  dof_direction INTEGER CHECK (dof_direction BETWEEN -6 AND 6 AND dof_direction <> 0),
  CHECK ((dof_node IS NULL) = (dof_direction IS NULL)),
  PRIMARY KEY (hit_id, channel)
) STRICT, WITHOUT ROWID;

-- FRF sets (one FrfMatrix each) and their FRFs.
CREATE TABLE frf_set (
  id              INTEGER PRIMARY KEY,
  specimen_id     INTEGER NOT NULL REFERENCES specimen(id) ON DELETE CASCADE,
  campaign_id     INTEGER REFERENCES campaign(id) ON DELETE CASCADE,
  name            TEXT NOT NULL,
  source          TEXT NOT NULL DEFAULT '',
  estimator       TEXT NOT NULL DEFAULT '',
  frf_type        INTEGER NOT NULL CHECK (frf_type IN (0, 1, 2)),  -- receptance, mobility, accelerance
  line_count      INTEGER NOT NULL CHECK (line_count > 0),
  frequency_hz    BLOB NOT NULL,  -- line_count float64, little endian
  created_utc     TEXT NOT NULL,
  UNIQUE (specimen_id, name)
) STRICT;
CREATE INDEX frf_set_campaign ON frf_set(campaign_id);

CREATE TABLE frf (
  id                  INTEGER PRIMARY KEY,
  frf_set_id          INTEGER NOT NULL REFERENCES frf_set(id) ON DELETE CASCADE,
  response_node       INTEGER NOT NULL,
  response_direction  INTEGER NOT NULL CHECK (response_direction BETWEEN -6 AND 6 AND response_direction <> 0),
  reference_node      INTEGER NOT NULL,
  reference_direction INTEGER NOT NULL CHECK (reference_direction BETWEEN -6 AND 6 AND reference_direction <> 0),
  response_index      INTEGER NOT NULL CHECK (response_index >= 0),
  reference_index     INTEGER NOT NULL CHECK (reference_index >= 0),
  h                   BLOB NOT NULL,  -- line_count complex float64 (re, im), little endian
  coherence           BLOB,           -- line_count float64, NULL when unknown
  UNIQUE (frf_set_id, response_index, reference_index)
) STRICT;

CREATE TABLE frf_hit (
  frf_set_id INTEGER NOT NULL REFERENCES frf_set(id) ON DELETE CASCADE,
  hit_id     INTEGER NOT NULL REFERENCES hit(id) ON DELETE CASCADE,
  PRIMARY KEY (frf_set_id, hit_id)
) STRICT, WITHOUT ROWID;
CREATE INDEX frf_hit_hit ON frf_hit(hit_id);

-- Modal results: modes and their shapes.
CREATE TABLE modal_result (
  id           INTEGER PRIMARY KEY,
  specimen_id  INTEGER NOT NULL REFERENCES specimen(id) ON DELETE CASCADE,
  frf_set_id   INTEGER REFERENCES frf_set(id) ON DELETE SET NULL,
  name         TEXT NOT NULL,
  method       TEXT NOT NULL DEFAULT '',
  band_low_hz  REAL NOT NULL DEFAULT 0,
  band_high_hz REAL NOT NULL DEFAULT 0,
  created_utc  TEXT NOT NULL,
  UNIQUE (specimen_id, name)
) STRICT;
CREATE INDEX modal_result_frf_set ON modal_result(frf_set_id);

CREATE TABLE mode (
  id              INTEGER PRIMARY KEY,
  modal_result_id INTEGER NOT NULL REFERENCES modal_result(id) ON DELETE CASCADE,
  mode_index      INTEGER NOT NULL CHECK (mode_index >= 0),
  frequency_hz    REAL NOT NULL CHECK (frequency_hz >= 0),
  damping_ratio   REAL NOT NULL,  -- viscous zeta
  UNIQUE (modal_result_id, mode_index)
) STRICT;

CREATE TABLE mode_shape (
  mode_id     INTEGER NOT NULL REFERENCES mode(id) ON DELETE CASCADE,
  dof_index   INTEGER NOT NULL CHECK (dof_index >= 0),
  dof_node    INTEGER NOT NULL,
  dof_direction INTEGER NOT NULL CHECK (dof_direction BETWEEN -6 AND 6 AND dof_direction <> 0),
  re          REAL NOT NULL,
  im          REAL NOT NULL,
  PRIMARY KEY (mode_id, dof_index)
) STRICT, WITHOUT ROWID;

-- Static and dynamic stiffness tests on a rig.
CREATE TABLE rig_test (
  id              INTEGER PRIMARY KEY,
  specimen_id     INTEGER NOT NULL REFERENCES specimen(id) ON DELETE CASCADE,
  rig_setup_id    INTEGER REFERENCES rig_setup(id) ON DELETE SET NULL,
  kind            TEXT NOT NULL CHECK (kind IN ('static', 'dynamic')),
  name            TEXT NOT NULL,
  parameters_json TEXT NOT NULL DEFAULT '{}',
  recorded_utc    TEXT NOT NULL,
  UNIQUE (specimen_id, name)
) STRICT;
CREATE INDEX rig_test_rig_setup ON rig_test(rig_setup_id);

CREATE TABLE rig_test_record (
  id             INTEGER PRIMARY KEY,
  rig_test_id    INTEGER NOT NULL REFERENCES rig_test(id) ON DELETE CASCADE,
  step           INTEGER NOT NULL CHECK (step >= 0),
  sample_rate_hz REAL NOT NULL CHECK (sample_rate_hz > 0),
  channel_count  INTEGER NOT NULL CHECK (channel_count > 0),
  sample_count   INTEGER NOT NULL CHECK (sample_count > 0),
  encoding       INTEGER NOT NULL CHECK (encoding IN (0, 1)),
  samples        BLOB NOT NULL,
  samples_crc32  INTEGER NOT NULL,
  UNIQUE (rig_test_id, step)
) STRICT;

CREATE TABLE rig_test_result (
  id          INTEGER PRIMARY KEY,
  rig_test_id INTEGER NOT NULL REFERENCES rig_test(id) ON DELETE CASCADE,
  quantity    TEXT NOT NULL,
  value       REAL NOT NULL,
  unit        TEXT NOT NULL,
  uncertainty REAL NOT NULL DEFAULT 0 CHECK (uncertainty >= 0)
) STRICT;
CREATE INDEX rig_test_result_test ON rig_test_result(rig_test_id);

-- Tyre tests: operating condition, measured points, identified parameters.
CREATE TABLE tyre_test (
  id                    INTEGER PRIMARY KEY,
  specimen_id           INTEGER NOT NULL REFERENCES specimen(id) ON DELETE CASCADE,
  rig_setup_id          INTEGER REFERENCES rig_setup(id) ON DELETE SET NULL,
  name                  TEXT NOT NULL,
  kind                  TEXT NOT NULL,
  inflation_pressure_pa REAL NOT NULL CHECK (inflation_pressure_pa >= 0),
  vertical_load_n       REAL NOT NULL,
  speed_m_s             REAL NOT NULL,
  recorded_utc          TEXT NOT NULL,
  UNIQUE (specimen_id, name)
) STRICT;
CREATE INDEX tyre_test_rig_setup ON tyre_test(rig_setup_id);

CREATE TABLE tyre_test_point (
  tyre_test_id          INTEGER NOT NULL REFERENCES tyre_test(id) ON DELETE CASCADE,
  point_index           INTEGER NOT NULL CHECK (point_index >= 0),
  slip_angle_rad        REAL NOT NULL,
  camber_rad            REAL NOT NULL,
  lateral_force_n       REAL NOT NULL,
  aligning_moment_nm    REAL NOT NULL,
  overturning_moment_nm REAL NOT NULL,
  PRIMARY KEY (tyre_test_id, point_index)
) STRICT, WITHOUT ROWID;

CREATE TABLE tyre_parameter (
  id           INTEGER PRIMARY KEY,
  tyre_test_id INTEGER NOT NULL REFERENCES tyre_test(id) ON DELETE CASCADE,
  name         TEXT NOT NULL,
  value        REAL NOT NULL,
  unit         TEXT NOT NULL,
  uncertainty  REAL NOT NULL DEFAULT 0 CHECK (uncertainty >= 0)
) STRICT;
CREATE INDEX tyre_parameter_test ON tyre_parameter(tyre_test_id);

-- Models of a specimen and the analyses (gap diagnoses) that compare them with tests.
CREATE TABLE model (
  id              INTEGER PRIMARY KEY,
  specimen_id     INTEGER NOT NULL REFERENCES specimen(id) ON DELETE CASCADE,
  name            TEXT NOT NULL,
  kind            TEXT NOT NULL CHECK (kind IN ('spatial', 'modal', 'lumped', 'stability')),
  source          TEXT NOT NULL DEFAULT '',
  parameters_json TEXT NOT NULL DEFAULT '{}',
  created_utc     TEXT NOT NULL,
  UNIQUE (specimen_id, name)
) STRICT;

CREATE TABLE analysis (
  id              INTEGER PRIMARY KEY,
  specimen_id     INTEGER NOT NULL REFERENCES specimen(id) ON DELETE CASCADE,
  model_id        INTEGER REFERENCES model(id) ON DELETE CASCADE,
  frf_set_id      INTEGER REFERENCES frf_set(id) ON DELETE CASCADE,
  modal_result_id INTEGER REFERENCES modal_result(id) ON DELETE CASCADE,
  rig_test_id     INTEGER REFERENCES rig_test(id) ON DELETE CASCADE,
  tyre_test_id    INTEGER REFERENCES tyre_test(id) ON DELETE CASCADE,
  kind            TEXT NOT NULL,
  name            TEXT NOT NULL,
  result_json     TEXT NOT NULL DEFAULT '{}',
  created_utc     TEXT NOT NULL,
  UNIQUE (specimen_id, name)
) STRICT;
CREATE INDEX analysis_model ON analysis(model_id);
CREATE INDEX analysis_frf_set ON analysis(frf_set_id);
CREATE INDEX analysis_modal_result ON analysis(modal_result_id);
CREATE INDEX analysis_rig_test ON analysis(rig_test_id);
CREATE INDEX analysis_tyre_test ON analysis(tyre_test_id);

CREATE TABLE gap_finding (
  id             INTEGER PRIMARY KEY,
  analysis_id    INTEGER NOT NULL REFERENCES analysis(id) ON DELETE CASCADE,
  band_low_hz    REAL NOT NULL,
  band_high_hz   REAL NOT NULL CHECK (band_high_hz >= band_low_hz),
  mode_index     INTEGER,
  dof_node       INTEGER,
  dof_direction  INTEGER CHECK (dof_direction BETWEEN -6 AND 6 AND dof_direction <> 0),
  condition      TEXT NOT NULL DEFAULT '',
  effect         TEXT NOT NULL,
  size           REAL NOT NULL,
  unit           TEXT NOT NULL DEFAULT '',
  uncertainty    REAL NOT NULL DEFAULT 0 CHECK (uncertainty >= 0),
  remaining_gap  REAL NOT NULL CHECK (remaining_gap >= 0),
  CHECK ((dof_node IS NULL) = (dof_direction IS NULL))
) STRICT;
CREATE INDEX gap_finding_analysis ON gap_finding(analysis_id);
)sql";

// Schema 2 (issue 15, campaign engine): the campaign's definition as JSON
// (devices/campaign/campaign_definition.h) and its roving schedule: every
// point in roving order, skipped or not with the technician's reason. Whether
// a point is done is not stored: it is done when it holds the definition's
// number of accepted hits, so a crash between a hit's commit and a status
// update cannot leave the two disagreeing.
constexpr const char* kSchema2 = R"sql(
ALTER TABLE campaign ADD COLUMN settings_json TEXT NOT NULL DEFAULT '{}';

CREATE TABLE campaign_point (
  campaign_id INTEGER NOT NULL REFERENCES campaign(id) ON DELETE CASCADE,
  position    INTEGER NOT NULL CHECK (position >= 0),
  node        INTEGER NOT NULL,
  direction   INTEGER NOT NULL CHECK (direction BETWEEN -6 AND 6 AND direction <> 0),
  skipped     INTEGER NOT NULL DEFAULT 0 CHECK (skipped IN (0, 1)),
  skip_reason TEXT NOT NULL DEFAULT '',
  PRIMARY KEY (campaign_id, position),
  UNIQUE (campaign_id, node, direction)
) STRICT, WITHOUT ROWID;
)sql";

// Rig and tyre tests run step by step (schema 3, issue 20, devices/rigtests): a test is
// 'running' while its steps are committed one transaction each, then
// 'complete', 'interrupted' (unplug, cancel, crash: the committed steps stay)
// or 'failed', with a note saying what is missing; a result may belong to one
// step (NULL: the whole test); tyre tests keep their raw records like rig tests.
const char* const kRigTestSteps = R"sql(
ALTER TABLE rig_test ADD COLUMN status TEXT NOT NULL DEFAULT 'complete'
  CHECK (status IN ('running', 'complete', 'interrupted', 'failed'));
ALTER TABLE rig_test ADD COLUMN status_note TEXT NOT NULL DEFAULT '';
ALTER TABLE rig_test_result ADD COLUMN step INTEGER CHECK (step IS NULL OR step >= 0);
ALTER TABLE tyre_test ADD COLUMN status TEXT NOT NULL DEFAULT 'complete'
  CHECK (status IN ('running', 'complete', 'interrupted', 'failed'));
ALTER TABLE tyre_test ADD COLUMN status_note TEXT NOT NULL DEFAULT '';
ALTER TABLE tyre_test ADD COLUMN parameters_json TEXT NOT NULL DEFAULT '{}';
ALTER TABLE tyre_parameter ADD COLUMN step INTEGER CHECK (step IS NULL OR step >= 0);

CREATE TABLE tyre_test_record (
  id             INTEGER PRIMARY KEY,
  tyre_test_id   INTEGER NOT NULL REFERENCES tyre_test(id) ON DELETE CASCADE,
  step           INTEGER NOT NULL CHECK (step >= 0),
  sample_rate_hz REAL NOT NULL CHECK (sample_rate_hz > 0),
  channel_count  INTEGER NOT NULL CHECK (channel_count > 0),
  sample_count   INTEGER NOT NULL CHECK (sample_count > 0),
  encoding       INTEGER NOT NULL CHECK (encoding IN (0, 1)),
  samples        BLOB NOT NULL,
  samples_crc32  INTEGER NOT NULL,
  UNIQUE (tyre_test_id, step)
) STRICT;
)sql";

// Schema 4 (issue 17): a CRC-32 over the content of every stored record that
// had none (hits and rig-test records carry samples_crc32 since schema 1),
// computed when the record is written and checked whenever it is read; the
// byte layouts hashed are in docs/formats/project.md, "Checksums". NULL means
// the record was written before schema 4 and cannot be checked.
// - frf_set.content_crc32: frf_type, line_count, frequency_hz bytes
// - frf.content_crc32: indices, DOFs, h bytes, coherence bytes
// - modal_result.content_crc32: band, then every mode and mode-shape entry
// - specimen.mesh_crc32: coordinate systems, nodes, lines, faces of its mesh
// - rig_test.content_crc32: kind, parameters_json and every result row
// - tyre_test.content_crc32: conditions, every point and parameter row
const char* const kSchema4Checksums = R"sql(
ALTER TABLE frf_set ADD COLUMN content_crc32 INTEGER;
ALTER TABLE frf ADD COLUMN content_crc32 INTEGER;
ALTER TABLE modal_result ADD COLUMN content_crc32 INTEGER;
ALTER TABLE specimen ADD COLUMN mesh_crc32 INTEGER;
ALTER TABLE rig_test ADD COLUMN content_crc32 INTEGER;
ALTER TABLE tyre_test ADD COLUMN content_crc32 INTEGER;
)sql";

// Schema 5 (issue 19): the standard errors of an identified mode's frequency
// and damping ratio, from the refinement that identified it, so that a kept
// identification shows them as its run did. NULL: none (peak picking, circle
// fit, a result kept before schema 5). In modal_result.content_crc32 only
// when present, so the checksums of older results stay valid.
const char* const kSchema5ModeUncertainty = R"sql(
ALTER TABLE mode ADD COLUMN frequency_std_hz REAL CHECK (frequency_std_hz IS NULL OR frequency_std_hz >= 0);
ALTER TABLE mode ADD COLUMN damping_ratio_std REAL CHECK (damping_ratio_std IS NULL OR damping_ratio_std >= 0);
)sql";

}  // namespace

const std::vector<const char*>& projectMigrations() {
  static const std::vector<const char*> migrations{kSchema1, kSchema2, kRigTestSteps, kSchema4Checksums,
                                                   kSchema5ModeUncertainty};
  return migrations;
}

const std::vector<const char*>& projectDataTables() {
  static const std::vector<const char*> tables{"specimen",
                                               "coordinate_system",
                                               "mesh_node",
                                               "mesh_line",
                                               "mesh_face",
                                               "rig_setup",
                                               "transducer",
                                               "campaign",
                                               "campaign_point",
                                               "hit",
                                               "hit_channel",
                                               "frf_set",
                                               "frf",
                                               "frf_hit",
                                               "modal_result",
                                               "mode",
                                               "mode_shape",
                                               "rig_test",
                                               "rig_test_record",
                                               "rig_test_result",
                                               "tyre_test",
                                               "tyre_test_point",
                                               "tyre_parameter",
                                               "model",
                                               "analysis",
                                               "gap_finding",
                                               "tyre_test_record"};
  return tables;
}

}  // namespace mozzi::core::io
