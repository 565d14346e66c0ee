// The campaign definition as ParameterSpec forms (what the new-campaign
// wizard shows): every section reads a definition into values its own specs
// accept, writing those values back changes nothing, edits land in the right
// fields, and bad values are refused with the key named and the definition
// left as it was.
#include "devices/campaign/campaign_form.h"

#include <gtest/gtest.h>

#include "devices/campaign/virtual_campaign.h"

namespace mozzi::devices::campaign {
namespace {

CampaignDefinition base() {
  auto d = virtualSpecimenCampaign("fork-a-with-wheel");
  EXPECT_TRUE(d.ok());
  return *d;
}

TEST(CampaignForm, ValuesOfEverySectionAreAcceptedByItsSpecsAndRoundTrip) {
  const CampaignDefinition d = base();
  for (FormSection section :
       {FormSection::Constraint, FormSection::Excitation, FormSection::Acquisition, FormSection::Channel}) {
    const auto specs = formSpecs(section);
    const auto values = formValues(d, section, 1);
    ASSERT_EQ(values.size(), specs.size());
    auto applied = applyParameters(specs, values);
    ASSERT_TRUE(applied.ok()) << applied.error().describe();
    CampaignDefinition copy = d;
    ASSERT_TRUE(applyForm(copy, section, values, 1).ok());
    EXPECT_EQ(definitionToJson(copy), definitionToJson(d));
  }
}

TEST(CampaignForm, EditsLandInTheirFields) {
  CampaignDefinition d = base();
  ASSERT_TRUE(
      applyForm(d, FormSection::Constraint,
                {{"constraint.kind", std::string("clamped")}, {"constraint.clamped_nodes", std::string("7, 8")}})
          .ok());
  EXPECT_EQ(d.constraint.kind, ConstraintKind::Clamped);
  EXPECT_EQ(d.constraint.clampedNodes, (std::vector<int>{7, 8}));
  ASSERT_TRUE(applyForm(d, FormSection::Excitation,
                        {{"excitation.kind", std::string("roving-accelerometer")},
                         {"excitation.fixed_point", std::string("3:+Y")},
                         {"campaign.hits_per_point", std::int64_t{3}}})
                  .ok());
  EXPECT_EQ(d.excitation, ExcitationKind::RovingAccelerometer);
  ASSERT_TRUE(d.fixedPoint.has_value());
  EXPECT_EQ(core::formatDof(*d.fixedPoint), "3:+Y");
  EXPECT_EQ(d.hitsPerPoint, 3);
  ASSERT_TRUE(applyForm(d, FormSection::Acquisition,
                        {{"acquisition.sample_rate", 2048.0},
                         {"acquisition.estimator", std::string("H2")},
                         {"rules.min_coherence", 0.8}})
                  .ok());
  EXPECT_EQ(d.acquisition.sampleRateHz, 2048.0);
  EXPECT_EQ(d.estimator, core::signal::FrfEstimator::H2);
  EXPECT_EQ(d.rules.minCoherence, 0.8);
  ASSERT_TRUE(
      applyForm(d, FormSection::Channel, {{"channel.serial", std::string("A-99")}, {"channel.sensitivity", 9.87}}, 2)
          .ok());
  EXPECT_EQ(d.channels[2].transducer.serial, "A-99");
  EXPECT_EQ(d.channels[2].transducer.sensitivityMvPerUnit, 9.87);
}

TEST(CampaignForm, BadValuesNameTheKeyAndChangeNothing) {
  const CampaignDefinition d = base();
  const auto before = definitionToJson(d);
  struct Case {
    FormSection section;
    ParameterMap values;
    std::string key;
  };
  const std::vector<Case> cases = {
      {FormSection::Constraint, {{"constraint.clamped_nodes", std::string("7 x")}}, "constraint.clamped_nodes"},
      {FormSection::Constraint, {{"constraint.kind", std::string("glued")}}, "constraint.kind"},
      {FormSection::Excitation, {{"excitation.fixed_point", std::string("3:+Q")}}, "excitation.fixed_point"},
      {FormSection::Excitation, {{"campaign.hits_per_point", std::int64_t{0}}}, "campaign.hits_per_point"},
      {FormSection::Acquisition, {{"acquisition.pre_trigger", 0.9}}, "acquisition.pre_trigger"},
      {FormSection::Acquisition, {{"no.such.key", 1.0}}, "no.such.key"},
      {FormSection::Channel, {{"channel.dof", std::string("")}}, "channel.dof"},
  };
  for (const auto& c : cases) {
    CampaignDefinition copy = d;
    auto r = applyForm(copy, c.section, c.values, 1);
    ASSERT_FALSE(r.ok()) << c.key;
    EXPECT_NE((r.error().where + " " + r.error().message).find(c.key), std::string::npos)
        << c.key << ": " << r.error().describe();
    EXPECT_EQ(definitionToJson(copy), before) << c.key;
  }
  CampaignDefinition copy = d;
  EXPECT_FALSE(applyForm(copy, FormSection::Channel, {}, 99).ok());  // no such channel
}

}  // namespace
}  // namespace mozzi::devices::campaign
