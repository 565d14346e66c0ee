#pragma once
// A campaign definition as ParameterSpec lists (STYLE 2), so that the
// new-campaign wizard builds its forms with the one form builder
// (views/panels/parameter_form.h) and the same keys could set a campaign from
// the command line: constraint, excitation, acquisition with the rejection
// rules, and one transducer channel. values() reads a definition into a
// complete ParameterMap, apply() writes a map back and validates; the errors
// name the key.

#include <string>
#include <vector>

#include "core/common/result.h"
#include "devices/campaign/campaign_definition.h"
#include "devices/common/parameters.h"

namespace mozzi::devices::campaign {

enum class FormSection { Constraint, Excitation, Acquisition, Channel };

// The parameters of one section, with English labels and help (views
// translate them in the context "Parameters").
std::vector<ParameterSpec> formSpecs(FormSection section);

// The section's values as the definition holds them (Channel: channel `index`).
ParameterMap formValues(const CampaignDefinition& definition, FormSection section, std::size_t index = 0);

// Writes the section's values into the definition (Channel: channel
// `index`). Keys missing from `values` keep the definition's value; a value
// the spec refuses or a field that does not parse (a DOF label, node labels)
// is an error naming the key, and the definition is left unchanged.
core::Result<void> applyForm(CampaignDefinition& definition, FormSection section, const ParameterMap& values,
                             std::size_t index = 0);

}  // namespace mozzi::devices::campaign
