// Round trips and integrity rules of the project store's data tables.
// Stored numbers are binary (float32 samples, float64 FRFs and REAL columns),
// so every round trip must be exact: tolerance 0 throughout.

#include <gtest/gtest.h>

#include <sqlite3.h>
#include <unistd.h>
#include <limits>

#include <cmath>
#include <filesystem>
#include <random>

#include "core/io/project_store.h"

namespace mozzi::core::io {
namespace {

namespace fs = std::filesystem;

class ProjectDataTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mozzi_data_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    auto store = ProjectStore::create(file("p.mozzi"), "test");
    ASSERT_TRUE(store.ok()) << store.error().describe();
    store_.emplace(std::move(*store));
    auto sp = store_->addSpecimen("Swing-arm A", "swing-arm", "thesis ch. 3");
    ASSERT_TRUE(sp.ok());
    specimen_ = *sp;
  }
  void TearDown() override {
    store_.reset();
    fs::remove_all(dir_);
  }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }

  std::int64_t count(const std::string& table) {
    sqlite3_stmt* stmt = nullptr;
    sqlite3_prepare_v2(store_->connection(), ("SELECT count(*) FROM " + table).c_str(), -1, &stmt, nullptr);
    sqlite3_step(stmt);
    const std::int64_t n = sqlite3_column_int64(stmt, 0);
    sqlite3_finalize(stmt);
    return n;
  }

  std::int64_t campaign() {
    StoredCampaign c;
    c.specimenId = specimen_;
    c.name = "campaign " + std::to_string(++campaigns_);
    auto id = store_->addCampaign(c);
    EXPECT_TRUE(id.ok()) << id.error().describe();
    return id.ok() ? *id : 0;
  }

  static StoredHit makeHit(std::int64_t campaignId, int sequence, Eigen::Index samples = 16384) {
    StoredHit h;
    h.campaignId = campaignId;
    h.sequence = sequence;
    h.point = Dof{21, Direction::Z, true};
    h.sampleRateHz = 25600.0;
    h.samples.resize(samples, 4);
    std::mt19937 rng(static_cast<unsigned>(sequence));
    std::normal_distribution<float> noise(0.0f, 1e-3f);
    for (Eigen::Index r = 0; r < samples; ++r) {
      const double t = static_cast<double>(r) / h.sampleRateHz;
      h.samples(r, 0) = r < 20 ? static_cast<float>(150.0 * std::sin(M_PI * r / 20.0)) : noise(rng);  // force [N]
      for (int c = 1; c < 4; ++c) {
        h.samples(r, c) = static_cast<float>(30.0 * std::exp(-15.0 * t) * std::sin(2 * M_PI * 95.0 * c * t)) +
                          noise(rng);  // acceleration [m/s^2]
      }
    }
    h.channels = {{Dof{1, Direction::Y, false}, "force", "N"},
                  {Dof{21, Direction::Z, true}, "acceleration", "m/s^2"},
                  {Dof{22, Direction::Z, false}, "acceleration", "m/s^2"},
                  {std::nullopt, "acceleration", "m/s^2"}};
    h.accepted = false;
    h.qualityFlags = kHitOverload | kHitTruncated;
    h.qualityReasons = "channel 2 overload; response not decayed";
    return h;
  }

  fs::path dir_;
  std::optional<ProjectStore> store_;
  std::int64_t specimen_ = 0;
  int campaigns_ = 0;
};

TEST_F(ProjectDataTest, HitRoundTripIsExactForBothEncodings) {
  const std::int64_t c = campaign();
  for (SampleEncoding encoding : {SampleEncoding::Raw, SampleEncoding::ShuffledZlib}) {
    store_->setHitEncoding(encoding);
    const int seq = encoding == SampleEncoding::Raw ? 1 : 2;
    const StoredHit in = makeHit(c, seq);
    auto id = store_->commitHit(in);
    ASSERT_TRUE(id.ok()) << id.error().describe();
    auto out = store_->hit(*id);
    ASSERT_TRUE(out.ok()) << out.error().describe();
    EXPECT_EQ(out->campaignId, c);
    EXPECT_EQ(out->sequence, seq);
    EXPECT_EQ(out->point, in.point);
    EXPECT_EQ(out->sampleRateHz, in.sampleRateHz);
    ASSERT_EQ(out->samples.rows(), 16384);
    ASSERT_EQ(out->samples.cols(), 4);
    EXPECT_TRUE(out->samples == in.samples);  // bit-exact: lossless
    ASSERT_EQ(out->channels.size(), 4u);
    EXPECT_EQ(out->channels[0].dof, in.channels[0].dof);
    EXPECT_EQ(out->channels[1].unit, "m/s^2");
    EXPECT_FALSE(out->channels[3].dof.has_value());
    EXPECT_FALSE(out->accepted);
    EXPECT_EQ(out->qualityFlags, kHitOverload | kHitTruncated);
    EXPECT_EQ(out->qualityReasons, in.qualityReasons);
    EXPECT_FALSE(out->recordedUtc.empty());
  }
  auto list = store_->hits(c);
  ASSERT_TRUE(list.ok());
  ASSERT_EQ(list->size(), 2u);
  // 4 x 16384 float32 = 262144 bytes raw; the shuffled-zlib blob must be
  // smaller for this decaying, low-noise signal (the point of the encoding).
  EXPECT_EQ((*list)[0].storedBytes, 262144);
  EXPECT_LT((*list)[1].storedBytes, 262144);
}

TEST_F(ProjectDataTest, HitAcceptanceCanChangeLater) {
  const std::int64_t c = campaign();
  auto id = store_->commitHit(makeHit(c, 1, 256));
  ASSERT_TRUE(id.ok());
  ASSERT_TRUE(store_->setHitAcceptance(*id, true, 0, "").ok());
  auto h = store_->hit(*id);
  ASSERT_TRUE(h.ok());
  EXPECT_TRUE(h->accepted);
  EXPECT_EQ(h->qualityFlags, 0u);
  auto missing = store_->setHitAcceptance(*id + 100, true, 0, "");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().code, ErrorCode::NotFound);
}

TEST_F(ProjectDataTest, BadHitsAreRejectedAndLeaveNothingBehind) {
  const std::int64_t c = campaign();
  StoredHit nan = makeHit(c, 1, 64);
  nan.samples(10, 2) = std::nanf("");
  auto r1 = store_->commitHit(nan);
  ASSERT_FALSE(r1.ok());
  EXPECT_NE(r1.error().message.find("sample 10 of channel 2"), std::string::npos) << r1.error().describe();

  StoredHit rate = makeHit(c, 1, 64);
  rate.sampleRateHz = 0.0;
  EXPECT_FALSE(store_->commitHit(rate).ok());

  ASSERT_TRUE(store_->commitHit(makeHit(c, 1, 64)).ok());
  // Same sequence again: the UNIQUE constraint refuses it and the
  // transaction rolls back, so no channel rows of it appear.
  auto dup = store_->commitHit(makeHit(c, 1, 64));
  ASSERT_FALSE(dup.ok());
  EXPECT_EQ(count("hit"), 1);
  EXPECT_EQ(count("hit_channel"), 4);

  StoredHit orphan = makeHit(c + 1000, 1, 64);  // no such campaign: foreign key
  auto fk = store_->commitHit(orphan);
  ASSERT_FALSE(fk.ok());
  EXPECT_NE(fk.error().message.find("FOREIGN KEY"), std::string::npos) << fk.error().describe();
  EXPECT_EQ(count("hit"), 1);
}

TEST_F(ProjectDataTest, CorruptedBlobIsReportedNotReturned) {
  const std::int64_t c = campaign();
  auto id = store_->commitHit(makeHit(c, 1, 1024));
  ASSERT_TRUE(id.ok());
  sqlite3* db = store_->connection();
  // Flip one byte of the stored samples behind the store's back.
  ASSERT_EQ(
      sqlite3_exec(db,
                   ("UPDATE hit SET samples = CAST(substr(samples, 1, 99) || x'ff' || substr(samples, 101) AS BLOB)"
                    " WHERE id = " +
                    std::to_string(*id))
                       .c_str(),
                   nullptr, nullptr, nullptr),
      SQLITE_OK);
  auto h = store_->hit(*id);
  ASSERT_FALSE(h.ok());
  EXPECT_EQ(h.error().code, ErrorCode::Corrupt);
  EXPECT_NE(h.error().message.find("CRC-32"), std::string::npos) << h.error().describe();

  // A header claiming 10^12 samples must fail before any allocation.
  ASSERT_EQ(sqlite3_exec(db, ("UPDATE hit SET sample_count = 1000000000000 WHERE id = " + std::to_string(*id)).c_str(),
                         nullptr, nullptr, nullptr),
            SQLITE_OK);
  auto huge = store_->hit(*id);
  ASSERT_FALSE(huge.ok());
  EXPECT_NE(huge.error().message.find("implausible"), std::string::npos) << huge.error().describe();
}

TEST_F(ProjectDataTest, MeshRoundTripAndForeignKeys) {
  StoredMesh mesh;
  StoredCoordinateSystem cs;
  cs.label = 2;
  cs.name = "steering head";
  cs.origin = Vector3(0.1, 0.2, 0.3);
  cs.rotation << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  mesh.coordinateSystems.push_back(cs);
  for (int i = 1; i <= 4; ++i) mesh.nodes.push_back({0, i, i == 4 ? 2 : 0, 0, Vector3(0.1 * i, -0.05 * i, 0.7)});
  mesh.lines = {{1, 2}, {2, 3}, {3, 4}};
  mesh.faces = {{1, 2, 3, 0}, {1, 2, 3, 4}};
  ASSERT_TRUE(store_->setMesh(specimen_, mesh).ok());
  auto out = store_->mesh(specimen_);
  ASSERT_TRUE(out.ok()) << out.error().describe();
  ASSERT_EQ(out->nodes.size(), 4u);
  EXPECT_EQ(out->nodes[3].definitionCs, 2);
  EXPECT_EQ(out->nodes[2].position, mesh.nodes[2].position);
  ASSERT_EQ(out->coordinateSystems.size(), 1u);
  EXPECT_EQ(out->coordinateSystems[0].rotation, cs.rotation);
  EXPECT_EQ(out->coordinateSystems[0].origin, cs.origin);
  ASSERT_EQ(out->lines.size(), 3u);
  EXPECT_EQ(out->lines[2].nodeB, 4);
  ASSERT_EQ(out->faces.size(), 2u);
  EXPECT_EQ(out->faces[0].nodeD, 0);
  EXPECT_EQ(out->faces[1].nodeD, 4);

  // A line to a node that is not in the mesh is refused and the old mesh stays.
  StoredMesh bad = mesh;
  bad.lines.push_back({1, 99});
  auto r = store_->setMesh(specimen_, bad);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("node 99"), std::string::npos);
  EXPECT_EQ(count("mesh_line"), 3);
}

TEST_F(ProjectDataTest, RigSetupWithTransducers) {
  StoredRigSetup s;
  s.specimenId = specimen_;
  s.name = "hammer + 3 accelerometers";
  s.rigKind = "impact-hammer";
  s.driver = "sim:swing-arm-a";
  s.transducers = {{0, 0, "force", "N", 2.25e-3, "PCB 086C03", "123", Dof{1, Direction::Y, false}},
                   {0, 1, "acceleration", "m/s^2", 1.02e-3, "PCB 356A16", "456", std::nullopt}};
  auto id = store_->addRigSetup(s);
  ASSERT_TRUE(id.ok()) << id.error().describe();
  auto out = store_->rigSetup(*id);
  ASSERT_TRUE(out.ok());
  ASSERT_EQ(out->transducers.size(), 2u);
  EXPECT_EQ(out->transducers[0].sensitivity, 2.25e-3);
  EXPECT_EQ(out->transducers[0].dof, s.transducers[0].dof);
  EXPECT_FALSE(out->transducers[1].dof.has_value());
  s.name = "bad";
  s.transducers[1].sensitivity = -1.0;
  EXPECT_FALSE(store_->addRigSetup(s).ok());
  EXPECT_EQ(count("rig_setup"), 1);  // rolled back with its first transducer
}

FrfMatrix sampleFrf(bool withCoherence) {
  FrfMatrix f;
  f.type = FrfType::Mobility;
  f.frequencyHz = Vector::LinSpaced(101, 0.0, 400.0);
  f.responses = {Dof{1, Direction::X, false}, Dof{2, Direction::Z, true}, Dof{3, Direction::RY, false}};
  f.references = {Dof{1, Direction::X, false}, Dof{5, Direction::Y, false}};
  for (int i = 0; i < 2; ++i) {
    ComplexMatrix h(101, 3);
    Matrix c(101, 3);
    for (int k = 0; k < 101; ++k) {
      for (int o = 0; o < 3; ++o) {
        h(k, o) = Complex(std::cos(0.01 * k * (o + 1) + i), std::sin(0.02 * k) / (1.0 + o + i));
        c(k, o) = 0.5 + 0.5 * std::cos(0.03 * k + o) * 0.9;
      }
    }
    f.h.push_back(h);
    if (withCoherence) f.coherence.push_back(c);
  }
  return f;
}

TEST_F(ProjectDataTest, FrfSetRoundTripIsExact) {
  const std::int64_t c = campaign();
  auto hit = store_->commitHit(makeHit(c, 1, 128));
  ASSERT_TRUE(hit.ok());
  for (bool coherence : {true, false}) {
    const FrfMatrix in = sampleFrf(coherence);
    FrfSetInfo info;
    info.specimenId = specimen_;
    info.campaignId = c;
    info.name = coherence ? "H1 with coherence" : "synthesised";
    info.estimator = "H1";
    auto id = store_->addFrfSet(info, in, {*hit});
    ASSERT_TRUE(id.ok()) << id.error().describe();
    auto out = store_->frfSet(*id);
    ASSERT_TRUE(out.ok()) << out.error().describe();
    EXPECT_EQ(out->type, FrfType::Mobility);
    EXPECT_EQ(out->frequencyHz, in.frequencyHz);
    EXPECT_EQ(out->responses, in.responses);
    EXPECT_EQ(out->references, in.references);
    ASSERT_EQ(out->h.size(), 2u);
    EXPECT_EQ(out->h[0], in.h[0]);
    EXPECT_EQ(out->h[1], in.h[1]);
    ASSERT_EQ(out->coherence.size(), in.coherence.size());
    if (coherence) {
      EXPECT_EQ(out->coherence[1], in.coherence[1]);
    }
  }
  auto sets = store_->frfSets();
  ASSERT_TRUE(sets.ok());
  ASSERT_EQ(sets->size(), 2u);
  EXPECT_EQ((*sets)[0].responseCount, 3);
  EXPECT_EQ((*sets)[0].referenceCount, 2);
  EXPECT_EQ((*sets)[0].lineCount, 101);
  EXPECT_EQ(count("frf_hit"), 2);

  FrfMatrix bad = sampleFrf(false);
  bad.h[1](7, 2) = Complex(std::nan(""), 0.0);
  FrfSetInfo info;
  info.specimenId = specimen_;
  info.name = "bad";
  EXPECT_FALSE(store_->addFrfSet(info, bad).ok());
}

TEST_F(ProjectDataTest, ModalResultRoundTrip) {
  ModalTable t;
  t.dofs = {Dof{1, Direction::X, false}, Dof{2, Direction::Z, true}};
  t.modes.push_back({41.5, 0.012, ComplexVector(2)});
  t.modes.push_back({97.25, 0.0301, ComplexVector(2)});
  t.modes[0].shape << Complex(1.0, 0.01), Complex(-0.5, 0.0);
  t.modes[1].shape << Complex(0.2, -0.1), Complex(1.0, 0.0);
  t.modes[1].frequencyStdHz = 0.0042;  // the refinement's standard errors; mode 1 has none
  t.modes[1].dampingRatioStd = 3.5e-5;
  ModalResultInfo info;
  info.specimenId = specimen_;
  info.name = "LSCE 0-200 Hz";
  info.method = "LSCE";
  info.bandHighHz = 200.0;
  auto id = store_->addModalResult(info, t);
  ASSERT_TRUE(id.ok()) << id.error().describe();
  auto out = store_->modalResult(*id);
  ASSERT_TRUE(out.ok()) << out.error().describe();
  EXPECT_EQ(out->dofs, t.dofs);
  ASSERT_EQ(out->modes.size(), 2u);
  EXPECT_EQ(out->modes[1].frequencyHz, 97.25);
  EXPECT_EQ(out->modes[1].dampingRatio, 0.0301);
  EXPECT_EQ(out->modes[0].shape, t.modes[0].shape);
  EXPECT_FALSE(out->modes[0].frequencyStdHz.has_value());
  EXPECT_FALSE(out->modes[0].dampingRatioStd.has_value());
  EXPECT_EQ(out->modes[1].frequencyStdHz, std::optional<double>(0.0042));
  EXPECT_EQ(out->modes[1].dampingRatioStd, std::optional<double>(3.5e-5));
  auto list = store_->modalResults();
  ASSERT_TRUE(list.ok());
  ASSERT_EQ(list->size(), 1u);
  EXPECT_EQ((*list)[0].modeCount, 2);
}

TEST_F(ProjectDataTest, AModeWithAnInvalidStandardErrorIsRefusedAndNamed) {
  for (const double bad : {-1e-3, std::nan(""), std::numeric_limits<double>::infinity()}) {
    ModalTable t;
    t.modes.push_back({41.5, 0.012});
    t.modes.push_back({97.25, 0.0301});
    t.modes[1].dampingRatioStd = bad;
    ModalResultInfo info;
    info.specimenId = specimen_;
    info.name = "bad standard error";
    auto id = store_->addModalResult(info, t);
    ASSERT_FALSE(id.ok()) << bad;
    EXPECT_NE(id.error().message.find("mode 2"), std::string::npos) << id.error().describe();
    EXPECT_NE(id.error().message.find("standard error"), std::string::npos) << id.error().describe();
  }
  auto list = store_->modalResults();
  ASSERT_TRUE(list.ok());
  EXPECT_TRUE(list->empty()) << "nothing of a refused result is kept";
}

TEST_F(ProjectDataTest, RigAndTyreTestsModelsAndAnalyses) {
  StoredRigTest rt;
  rt.specimenId = specimen_;
  rt.kind = StoredRigTest::Kind::Dynamic;
  rt.name = "torsion 5 Hz";
  rt.results = {{"torsional stiffness", 1.8e5, "N m/rad", 2.0e3}};
  auto rtId = store_->addRigTest(rt);
  ASSERT_TRUE(rtId.ok()) << rtId.error().describe();
  Eigen::MatrixXf rec = Eigen::MatrixXf::Random(500, 3);
  ASSERT_TRUE(store_->addRigTestRecord(*rtId, 0, 1000.0, rec).ok());
  double rate = 0;
  auto recOut = store_->rigTestRecord(*rtId, 0, &rate);
  ASSERT_TRUE(recOut.ok()) << recOut.error().describe();
  EXPECT_TRUE(*recOut == rec);
  EXPECT_EQ(rate, 1000.0);
  auto rtOut = store_->rigTest(*rtId);
  ASSERT_TRUE(rtOut.ok());
  EXPECT_EQ(rtOut->kind, StoredRigTest::Kind::Dynamic);
  ASSERT_EQ(rtOut->results.size(), 1u);
  EXPECT_EQ(rtOut->results[0].value, 1.8e5);

  StoredTyreTest tt;
  tt.specimenId = specimen_;
  tt.name = "120/70 ZR17 cornering";
  tt.kind = "cornering";
  tt.inflationPressurePa = 2.5e5;
  tt.verticalLoadN = 1500.0;
  tt.speedMps = 0.1;
  tt.points = {{0.01, 0.0, 210.0, 1.5, 0.0}, {0.02, 0.0, 400.0, 2.6, 0.1}};
  tt.parameters = {{"cornering stiffness", 2.0e4, "N/rad", 300.0}};
  auto ttId = store_->addTyreTest(tt);
  ASSERT_TRUE(ttId.ok()) << ttId.error().describe();
  auto ttOut = store_->tyreTest(*ttId);
  ASSERT_TRUE(ttOut.ok());
  ASSERT_EQ(ttOut->points.size(), 2u);
  EXPECT_EQ(ttOut->points[1].lateralForceN, 400.0);
  EXPECT_EQ(ttOut->inflationPressurePa, 2.5e5);

  StoredModel m;
  m.specimenId = specimen_;
  m.name = "beam model";
  m.kind = "spatial";
  auto mId = store_->addModel(m);
  ASSERT_TRUE(mId.ok()) << mId.error().describe();
  StoredAnalysis a;
  a.specimenId = specimen_;
  a.modelId = *mId;
  a.tyreTestId = *ttId;
  a.name = "gap 1";
  StoredAnalysis::Finding f;
  f.bandLowHz = 80;
  f.bandHighHz = 120;
  f.modeIndex = 2;
  f.dof = Dof{3, Direction::Y, false};
  f.effect = "joint compliance";
  f.size = 1.2e-6;
  f.unit = "rad/(N m)";
  f.remainingGap = 0.15;
  a.findings = {f};
  auto aId = store_->addAnalysis(a);
  ASSERT_TRUE(aId.ok()) << aId.error().describe();
  auto aOut = store_->analysis(*aId);
  ASSERT_TRUE(aOut.ok());
  ASSERT_EQ(aOut->findings.size(), 1u);
  EXPECT_EQ(aOut->findings[0].dof, f.dof);
  EXPECT_EQ(aOut->findings[0].modeIndex, 2);
  EXPECT_EQ(aOut->modelId, *mId);

  // Deleting the model removes the analysis it was made with (CASCADE).
  ASSERT_EQ(sqlite3_exec(store_->connection(), ("DELETE FROM model WHERE id = " + std::to_string(*mId)).c_str(),
                         nullptr, nullptr, nullptr),
            SQLITE_OK);
  EXPECT_EQ(count("analysis"), 0);
  EXPECT_EQ(count("gap_finding"), 0);
}

TEST_F(ProjectDataTest, DeletingASpecimenCascadesAndSetNullKeepsCampaigns) {
  StoredRigSetup s;
  s.specimenId = specimen_;
  s.name = "rig";
  s.rigKind = "impact-hammer";
  s.transducers = {{0, 0, "force", "N", 1e-3, "", "", std::nullopt}};
  auto setup = store_->addRigSetup(s);
  ASSERT_TRUE(setup.ok());
  StoredCampaign cc;
  cc.specimenId = specimen_;
  cc.rigSetupId = *setup;
  cc.name = "with rig";
  auto c = store_->addCampaign(cc);
  ASSERT_TRUE(c.ok());
  ASSERT_TRUE(store_->commitHit(makeHit(*c, 1, 64)).ok());
  // Removing the rig set-up keeps the campaign and its hits (SET NULL).
  ASSERT_EQ(sqlite3_exec(store_->connection(), "DELETE FROM rig_setup", nullptr, nullptr, nullptr), SQLITE_OK);
  auto list = store_->campaigns(specimen_);
  ASSERT_TRUE(list.ok());
  ASSERT_EQ(list->size(), 1u);
  EXPECT_FALSE((*list)[0].rigSetupId.has_value());
  EXPECT_EQ(count("hit"), 1);
  EXPECT_EQ(count("transducer"), 0);

  FrfSetInfo info;
  info.specimenId = specimen_;
  info.campaignId = *c;
  info.name = "H1";
  ASSERT_TRUE(store_->addFrfSet(info, sampleFrf(true)).ok());
  ASSERT_TRUE(store_->deleteSpecimen(specimen_).ok());
  for (const char* table : {"campaign", "hit", "hit_channel", "frf_set", "frf"}) EXPECT_EQ(count(table), 0) << table;
  EXPECT_EQ(store_->deleteSpecimen(specimen_).error().code, ErrorCode::NotFound);
}

// Every row the store changes must change inside an explicit transaction:
// SQLite's update hook runs for each row, and autocommit must be off then.
TEST_F(ProjectDataTest, NothingIsWrittenOutsideATransaction) {
  struct Counter {
    sqlite3* db;
    int changes = 0;
    int outside = 0;
  } counter{store_->connection()};
  sqlite3_update_hook(
      store_->connection(),
      [](void* arg, int, const char*, const char*, sqlite3_int64) {
        auto* c = static_cast<Counter*>(arg);
        ++c->changes;
        if (sqlite3_get_autocommit(c->db)) ++c->outside;
      },
      &counter);
  const std::int64_t c = campaign();
  ASSERT_TRUE(store_->commitHit(makeHit(c, 1, 64)).ok());
  ASSERT_TRUE(store_->setHitAcceptance(1, true, 0, "").ok());
  FrfSetInfo info;
  info.specimenId = specimen_;
  info.name = "H1";
  ASSERT_TRUE(store_->addFrfSet(info, sampleFrf(true)).ok());
  ASSERT_TRUE(store_->addSpecimen("Fork B", "fork", "").ok());
  StoredMesh mesh;
  mesh.nodes.push_back({0, 1, 0, 0, Vector3(0, 0, 0)});
  ASSERT_TRUE(store_->setMesh(specimen_, mesh).ok());
  ASSERT_TRUE(store_->deleteSpecimen(specimen_).ok());
  sqlite3_update_hook(store_->connection(), nullptr, nullptr);
  EXPECT_GT(counter.changes, 10);
  EXPECT_EQ(counter.outside, 0);
}

TEST_F(ProjectDataTest, CheckpointMovesTheWalIntoTheDatabase) {
  const std::int64_t c = campaign();
  ASSERT_TRUE(store_->commitHit(makeHit(c, 1)).ok());
  const auto before = fs::file_size(file("p.mozzi"));
  ASSERT_TRUE(store_->checkpoint().ok());
  // The 256 KiB hit now lives in the main file, not only in the WAL.
  EXPECT_GE(fs::file_size(file("p.mozzi")), before + 262144);
  auto h = store_->hit(1);
  ASSERT_TRUE(h.ok());
  EXPECT_EQ(h->samples.rows(), 16384);
}

TEST_F(ProjectDataTest, ReadOnlyStoreRefusesEveryWrite) {
  auto second = ProjectStore::open(file("p.mozzi"));
  ASSERT_TRUE(second.ok());
  ASSERT_TRUE(second->isReadOnly());
  StoredHit h = makeHit(1, 1, 8);
  EXPECT_EQ(second->commitHit(h).error().code, ErrorCode::Locked);
  StoredCampaign c;
  c.specimenId = specimen_;
  c.name = "x";
  EXPECT_EQ(second->addCampaign(c).error().code, ErrorCode::Locked);
  EXPECT_EQ(second->deleteSpecimen(specimen_).error().code, ErrorCode::Locked);
  EXPECT_EQ(second->checkpoint().error().code, ErrorCode::Locked);
  // Reading works while the first instance writes.
  auto s = second->summary();
  ASSERT_TRUE(s.ok()) << s.error().describe();
  EXPECT_EQ(s->specimens.size(), 1u);
}

}  // namespace
}  // namespace mozzi::core::io
