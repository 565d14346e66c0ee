// Forks the project keeps (the Lumped Fork page's analyses) read into the
// stability models' fork parameters. Ground truth: Table 12's inputs kept in
// the page's JSON give back thesisLumpedForkModel's models 1 and 2 (the mass
// arm below the bending axis, 0.405 and 0.581 m, from L_i minus the wheel
// centre's 0.265 m), exactly; a bicycle fork's bending and torsion as kept.
#include "core/stability/kept_forks.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/io/project_store.h"

namespace mozzi::core::stability {
namespace {

// The JSON the Lumped Fork page keeps (keys of `mozzi-cli fork lumped --json`).
std::string table12Json() {
  auto model = [](double k, double arm, double J, double c) {
    return nlohmann::json{{"stiffness_Nm_per_rad", k},
                          {"arm_m", arm},
                          {"inertia_kgm2", J},
                          {"pure_moment_kgm2", 0.0},
                          {"frequency_Hz", 0},
                          {"damping_Nms_per_rad", c},
                          {"zeta", 0.024}};
  };
  return nlohmann::json{{"fork", "motorcycle"},
                        {"inputs", {{"vibrating_mass_kg", 11.0}, {"wheel_centre_height_m", 0.670 - 0.405}}},
                        {"models",
                         {{"model1", model(28e3, 0.670, 2.085, 11.6)},
                          {"model2", model(78.4e3, 0.846, 3.995, 26.9)},
                          {"model3", model(28e3, 0.670, 1.426, 9.6)}}}}
      .dump();
}

TEST(KeptForks, Table12InputsGiveTheThesisModels) {
  auto f = keptForkFromJson(table12Json(), "lumped-fork");
  ASSERT_TRUE(f.ok()) << f.error().describe();
  EXPECT_TRUE(f->motorcycle);
  for (int i : {1, 2, 3}) {
    const auto thesis = thesisLumpedForkModel(i).value();
    const auto& kept = f->lumped[static_cast<std::size_t>(i - 1)];
    ASSERT_TRUE(kept.has_value());
    EXPECT_EQ(kept->stiffness, thesis.stiffness);
    EXPECT_EQ(kept->damping, thesis.damping);
    EXPECT_EQ(kept->inertia, thesis.inertia);
    EXPECT_EQ(kept->mass, thesis.mass);
    EXPECT_NEAR(kept->massArm, thesis.massArm, 1e-15) << i;
    EXPECT_EQ(kept->axisFromContact, thesis.axisFromContact);
  }
}

TEST(KeptForks, BicycleForkAndErrors) {
  const std::string json =
      nlohmann::json{
          {"fork", "bicycle"},
          {"torsion", {{"stiffness_alone_Nm_per_rad", 1938.0}, {"damping_Nms_per_rad", 0.3}}},
          {"bending", {{"bend_arm_hW_m", 0.21}, {"stiffness_Nm_per_rad", 5635.0}, {"damping_Nms_per_rad", 0.8}}}}
          .dump();
  auto f = keptForkFromJson(json, "bicycle-fork");
  ASSERT_TRUE(f.ok()) << f.error().describe();
  EXPECT_FALSE(f->motorcycle);
  ASSERT_TRUE(f->bending && f->torsion);
  EXPECT_EQ(f->bending->stiffness, thesisSteelForkBending().stiffness);
  EXPECT_EQ(f->bending->hW, thesisSteelForkBending().hW);
  EXPECT_EQ(f->torsion->stiffness, thesisSteelForkTorsion().stiffness);
  EXPECT_EQ(f->torsion->damping, thesisSteelForkTorsion().damping);
  EXPECT_FALSE(keptForkFromJson("{}", "lumped-fork").ok());
  EXPECT_FALSE(keptForkFromJson("not json", "bicycle-fork").ok());
  EXPECT_FALSE(keptForkFromJson(json, "gap-diagnosis").ok());
}

TEST(KeptForks, FromTheProjectsAnalyses) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("mozzi_kept_forks_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    auto store = io::ProjectStore::create((dir / "p.mozzi").string(), "test");
    ASSERT_TRUE(store.ok());
    auto fork = store->addSpecimen("Fork A", "fork", "test");
    ASSERT_TRUE(fork.ok());
    io::StoredAnalysis a;
    a.specimenId = *fork;
    a.kind = "lumped-fork";
    a.name = "Lumped fork models 1 to 3";
    a.resultJson = table12Json();
    ASSERT_TRUE(store->addAnalysis(a).ok());
    a.kind = "lumped-fork";
    a.name = "broken";
    a.resultJson = "{\"models\": {}}";
    auto broken = store->addAnalysis(a);
    ASSERT_TRUE(broken.ok());
    a.kind = "relaxation-prediction";  // not a fork: left out
    a.name = "relaxation";
    a.resultJson = "{}";
    ASSERT_TRUE(store->addAnalysis(a).ok());
    std::vector<std::int64_t> unreadable;
    auto forks = keptForks(*store, &unreadable);
    ASSERT_TRUE(forks.ok());
    ASSERT_EQ(forks->size(), 1u);
    EXPECT_EQ((*forks)[0].name, "Lumped fork models 1 to 3");
    EXPECT_EQ((*forks)[0].specimenId, *fork);
    EXPECT_EQ(unreadable, std::vector<std::int64_t>{*broken});
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mozzi::core::stability
