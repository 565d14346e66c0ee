// mozzi-model/1 files: what a valid file gives, and that every violation is an
// error naming the field and index (docs/formats.md, "mozzi-model/1").
#include <gtest/gtest.h>

#include <string>

#include "core/gap/structural/model_file.h"
#include "validation/gap/structural_benchmark.h"

namespace mozzi::core::gap::structural {
namespace {

// Two masses on springs: ground - k1 - x1 - k2 - x2.
std::string twoDof(const std::string& extra = "", const std::string& k = "[[3000, -1000], [-1000, 1000]]",
                   const std::string& m = "[[2, 0], [0, 1]]",
                   const std::string& damping = R"("modal_damping": [0.01, 0.02])") {
  return R"({"schema": "mozzi-model/1", "name": "two", "dofs": ["1+Z", "2+Z"], "M": )" + m + R"(, "K": )" + k + ", " +
         damping +
         R"(, "springs": [{"name": "k1", "a": "1+Z", "b": "ground", "stiffness": 2000},
                          {"name": "k2", "a": "1+Z", "b": "2+Z", "stiffness": 1000}],
            "masses": [{"name": "tip", "dof": "2+Z", "mass": 1}],
            "parameters": [{"name": "k1_scale", "acts_on": ["k1"], "nominal": 1, "lower": 0.5, "upper": 2, "prior_sigma": 0.1})" +
         extra + "]}";
}

void expectError(const std::string& text, const std::string& field) {
  auto r = parseModelJson(text, "test.json");
  ASSERT_FALSE(r.ok()) << "accepted: " << text;
  EXPECT_NE(r.error().message.find(field), std::string::npos) << r.error().describe() << " should name " << field;
  EXPECT_EQ(r.error().where, "test.json");
}

TEST(ModelFile, ValidTwoDofModel) {
  auto r = parseModelJson(twoDof(), "test.json");
  ASSERT_TRUE(r.ok()) << r.error().describe();
  EXPECT_EQ(r->dofCount(), 2);
  EXPECT_EQ(r->labels[1], "2+Z");
  EXPECT_TRUE(r->usesModalDamping());
  EXPECT_DOUBLE_EQ(r->modalDamping[1], 0.02);
  ASSERT_EQ(r->springs.size(), 2u);
  EXPECT_TRUE(r->springs[0].grounded());
  EXPECT_EQ(r->springs[1].b, 1);
  ASSERT_EQ(r->parameters.size(), 1u);
  EXPECT_DOUBLE_EQ(r->parameters[0].priorSigma, 0.1);
  EXPECT_TRUE(r->t.isIdentity());
}

TEST(ModelFile, WriteAndReadBack) {
  const auto s = gap_bench::viscousC(gap_bench::forkWheel());
  auto text = writeModelJson(s.model);
  ASSERT_TRUE(text.ok()) << text.error().describe();
  auto back = parseModelJson(*text, "round trip");
  ASSERT_TRUE(back.ok()) << back.error().describe();
  EXPECT_EQ(back->labels, std::vector<std::string>(s.model.labels.begin(), s.model.labels.end()));
  EXPECT_LT((back->k - s.model.k).norm(), 1e-9 * s.model.k.norm());
  EXPECT_LT((back->c - s.model.c).norm(), 1e-9 * s.model.c.norm());
  EXPECT_EQ(back->springs.size(), s.model.springs.size());
  EXPECT_EQ(back->parameters[1].actsOn, s.model.parameters[1].actsOn);
}

TEST(ModelFile, ErrorsNameFieldAndIndex) {
  expectError("{", "JSON");
  expectError(R"({"schema": "mozzi-model/2"})", "schema");
  expectError(twoDof("", "[[3000, -1000], [-999, 1000]]"), "K[0][1]");
  expectError(twoDof("", "[[3000, -1000], [-1000]]"), "K[1]");
  expectError(twoDof("", "[[3000, -1000], [-1000, \"x\"]]"), "K[1][1]");
  expectError(twoDof("", "[[3000, -1000], [-1000, 1000]]", "[[2, 0], [0, -1]]"), "M");
  expectError(twoDof("", "[[-3000, 0], [0, 1000]]"), "K");
  expectError(twoDof("", "[[3000, -1000], [-1000, 1000]]", "[[2, 0], [0, 1]]", R"("modal_damping": [0.01])"),
              "modal_damping");
  expectError(twoDof("", "[[3000, -1000], [-1000, 1000]]", "[[2, 0], [0, 1]]", R"("modal_damping": [0.01, 1.5])"),
              "modal_damping[1]");
  expectError(twoDof("", "[[3000, -1000], [-1000, 1000]]", "[[2, 0], [0, 1]]",
                     R"("modal_damping": [0.01, 0.01], "C": [[1, 0], [0, 1]])"),
              "C");
  expectError(twoDof(R"(, {"name": "bad", "acts_on": ["nope"], "lower": 0.5, "upper": 2})"),
              "parameters[1].acts_on[0]");
  expectError(twoDof(R"(, {"name": "bad", "acts_on": ["k2"], "nominal": 3, "lower": 0.5, "upper": 2})"),
              "parameters[1]");
  std::string unknownDof = twoDof();
  unknownDof.replace(unknownDof.find(R"("b": "2+Z")"), 10, R"("b": "7+Z")");
  expectError(unknownDof, "springs[1].b");
  std::string repeated = twoDof();
  repeated.replace(repeated.find(R"(["1+Z", "2+Z"])"), 14, R"(["1+Z", "1-Z"])");
  expectError(repeated, "dofs[1]");
  std::string badLabel = twoDof();
  badLabel.replace(badLabel.find(R"(["1+Z", "2+Z"])"), 14, R"(["1+Z", "2+W"])");
  expectError(badLabel, "dofs[1]");
}

// A complete modal model (UFF 55 with modal masses) is the spatial model in
// modal coordinates: same frequencies.
TEST(ModelFile, ModalDataGivesModalCoordinates) {
  io::uff::ModalData modal;
  modal.dofs = {*parseDof("1+Z"), *parseDof("2+Z")};
  modal.frequencyHz = Vector(2);
  modal.frequencyHz << 12.0, 30.0;
  modal.dampingRatio = Vector::Constant(2, 0.01);
  modal.modalMass = Vector(2);
  modal.modalMass << 4.0, 0.0;
  modal.shapes = ComplexMatrix::Ones(2, 2);
  auto refused = modelFromModalData(modal);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().where.find("mode 2"), std::string::npos);
  modal.modalMass[1] = 1.0;
  modal.shapes(1, 1) = -1.0;
  auto model = modelFromModalData(modal);
  ASSERT_TRUE(model.ok()) << model.error().describe();
  EXPECT_NEAR(std::sqrt(model->k(0, 0)) / (2 * M_PI), 12.0, 1e-12);
  // Unit modal mass: shapes of a 4 kg modal mass are divided by 2.
  EXPECT_NEAR(model->t(0, 0), 0.5, 1e-15);
}

}  // namespace
}  // namespace mozzi::core::gap::structural
