// Imported twist CSVs as stored-test views (devices/rigtests/imported_twist.h):
// a static ramp and a sweep written here from rigid plate rotations about
// chosen axes give those axes and the analytic k_lat and a_tw; kept in a
// project they read back through readStiffnessTest unchanged (the same keys,
// values and uncertainties, the same per-step axes and laser phasors).
#include "devices/rigtests/imported_twist.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <sstream>

namespace mozzi::devices::rigtests {
namespace {

namespace st = core::stiffness;
constexpr double kPi = 3.14159265358979323846;
const char* kPlate = "sensor,0.2,-0.3\nsensor,0,-0.3\nsensor,0,0\nsensor,0.2,0\nload,0.1,-0.651\n";
const std::vector<core::Vector2> kSensors{{0.2, -0.3}, {0, -0.3}, {0, 0}, {0.2, 0}};
const core::Vector2 kLoad(0.1, -0.651);

// Out-of-plane displacement per unit rotation about the axis through q inclined beta.
double arm(const core::Vector2& q, double beta, const core::Vector2& p) {
  return (p(0) - q(0)) * std::cos(beta) - (p(1) - q(1)) * std::sin(beta);
}

TEST(ImportedTwist, StaticAndDynamicViewsKeepTheirAxesInAProject) {
  const core::Vector2 q(0.05, -0.1);
  const double beta = 20 * kPi / 180, c = 5e-6;  // rad/N
  std::ostringstream s;
  s.precision(17);
  s << kPlate;
  for (int k = 0; k <= 10; ++k) {
    const double f = -300 + 60 * k;
    s << f;
    for (const auto& p : kSensors) s << "," << c * f * arm(q, beta, p);
    s << "\n";
  }
  auto csv = st::parsePlateCsv(s.str(), "ramp.csv", true);
  ASSERT_TRUE(csv.ok()) << csv.error().describe();
  auto view = staticViewFromCsv(*csv, "ramp");
  ASSERT_TRUE(view.ok()) << view.error().describe();
  ASSERT_TRUE(view->axis.has_value());
  // A force F at the load point turns the plate by c F and moves the load
  // point by c F a (a its arm): k_lat = 1 / (c a), k_tw = k_lat a^2 = a / c
  // (eq. 29, 30), to round-off of the regression (1e-9 relative).
  const double a = std::abs(arm(q, beta, kLoad));
  EXPECT_NEAR(view->result("a_tw")->value, a, 1e-12);
  EXPECT_NEAR(view->result("k_lat")->value, 1.0 / (c * a), 1e-9 / (c * a));
  EXPECT_NEAR(view->result("k_tw")->value, a / c, 1e-9 * a / c);
  EXPECT_NEAR(std::abs(arm(q, beta, view->axis->point)), 0.0, 1e-12);

  std::ostringstream d;
  d.precision(17);
  d << kPlate << "freq_Hz,A1,phi1,A2,phi2,A3,phi3,A4,phi4\n";
  const double betas[] = {0.3, 0.6};
  for (int k = 0; k < 2; ++k) {
    d << 5 * (k + 1);
    for (const auto& p : kSensors) {
      const double w = 1e-3 * arm(q, betas[k], p);
      d << "," << std::abs(w) << "," << (w < 0 ? 180 : 0);
    }
    d << "\n";
  }
  auto dcsv = st::parsePlateCsv(d.str(), "sweep.csv", true);
  ASSERT_TRUE(dcsv.ok());
  std::string note;
  auto sweep = dynamicViewFromCsv(*dcsv, "sweep", &note);
  ASSERT_TRUE(sweep.ok()) << sweep.error().describe();
  EXPECT_TRUE(note.empty()) << note;
  ASSERT_EQ(sweep->steps.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    ASSERT_TRUE(sweep->steps[static_cast<std::size_t>(k)].axis.has_value());
    EXPECT_NEAR(sweep->steps[static_cast<std::size_t>(k)].axis->beta, betas[k], 1e-9);
  }

  const auto path =
      (std::filesystem::temp_directory_path() / ("mozzi_imported_twist_" + std::to_string(::getpid()) + ".mozzi"))
          .string();
  std::filesystem::remove(path);
  auto store = core::io::ProjectStore::create(path, "test");
  ASSERT_TRUE(store.ok()) << store.error().describe();
  auto specimen = store->addSpecimen("plate", "frame", "");
  ASSERT_TRUE(specimen.ok());
  for (const StiffnessTestView* v : {&*view, &*sweep}) {
    auto id = storeImportedTest(*store, *specimen, *v, "/data/" + v->name + ".csv");
    ASSERT_TRUE(id.ok()) << id.error().describe();
    auto back = readStiffnessTest(*store, *id);
    ASSERT_TRUE(back.ok()) << back.error().describe();
    EXPECT_EQ(back->name, v->name);
    EXPECT_EQ(back->dynamic, v->dynamic);
    EXPECT_EQ(back->loadPoint, v->loadPoint);
    EXPECT_EQ(back->laserPoints, v->laserPoints);
    for (const auto& [key, q0] : v->results) {
      ASSERT_NE(back->result(key), nullptr) << key;
      EXPECT_EQ(back->result(key)->value, q0.value) << key;
      EXPECT_EQ(back->result(key)->uncertainty, q0.uncertainty) << key;
    }
    ASSERT_EQ(back->steps.size(), v->steps.size());
    for (std::size_t k = 0; k < v->steps.size(); ++k) {
      EXPECT_EQ(back->steps[k].frequencyHz, v->steps[k].frequencyHz);
      ASSERT_TRUE(back->steps[k].axis.has_value());
      EXPECT_NEAR(back->steps[k].axis->beta, v->steps[k].axis->beta, 1e-12);
      EXPECT_LT((back->steps[k].laserPhasors - v->steps[k].laserPhasors).norm(), 1e-15);
    }
    if (!v->dynamic) {
      ASSERT_TRUE(back->axis.has_value());
      EXPECT_NEAR(back->axis->beta, v->axis->beta, 1e-12);
    }
  }
  // The same name again is made unique.
  auto again = storeImportedTest(*store, *specimen, *view, "/data/ramp.csv");
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(store->rigTest(*again)->name, "ramp (2)");
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace mozzi::devices::rigtests
