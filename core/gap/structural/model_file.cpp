#include "core/gap/structural/model_file.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/common/text.h"

namespace mozzi::core::gap::structural {
namespace {

using nlohmann::json;

// A file of this many DOFs is far beyond a lumped model; the limit keeps a
// hostile "dofs" list from allocating N^2 matrices.
constexpr int kMaxDofs = 2000;

Error parseError(const std::string& where, const std::string& field, const std::string& message) {
  return makeError(ErrorCode::ParseError, field + ": " + message, where);
}

Result<double> finiteNumber(const json& value, const std::string& where, const std::string& field) {
  if (!value.is_number()) return parseError(where, field, "expected a number");
  const double x = value.get<double>();
  if (!std::isfinite(x)) return parseError(where, field, "not a finite number");
  return x;
}

Result<Matrix> squareMatrix(const json& root, const char* key, int n, const std::string& where) {
  const json& a = root.at(key);
  if (!a.is_array() || static_cast<int>(a.size()) != n) {
    return parseError(where, key, "expected an array of " + std::to_string(n) + " rows (one per DOF)");
  }
  Matrix out(n, n);
  for (int i = 0; i < n; ++i) {
    const json& row = a[static_cast<std::size_t>(i)];
    const std::string rowName = std::string(key) + "[" + std::to_string(i) + "]";
    if (!row.is_array() || static_cast<int>(row.size()) != n) {
      return parseError(where, rowName, "expected " + std::to_string(n) + " numbers");
    }
    for (int j = 0; j < n; ++j) {
      MOZZI_TRY_ASSIGN(out(i, j),
                       finiteNumber(row[static_cast<std::size_t>(j)], where, rowName + "[" + std::to_string(j) + "]"));
    }
  }
  return out;
}

// Symmetric to 1e-9 of the largest entry (round-off of a file written with 12
// or more significant digits), then definiteness from the eigenvalues with the
// same relative tolerance.
Result<void> checkSymmetricDefinite(const Matrix& a, const char* key, bool strictlyPositive, const std::string& where) {
  const double scale = a.cwiseAbs().maxCoeff();
  const double tol = 1e-9 * std::max(scale, 1e-300);
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    for (Eigen::Index j = i + 1; j < a.cols(); ++j) {
      if (std::abs(a(i, j) - a(j, i)) > tol) {
        return parseError(where, std::string(key) + "[" + std::to_string(i) + "][" + std::to_string(j) + "]",
                          "matrix is not symmetric (" + formatNumber(a(i, j)) + " against " + formatNumber(a(j, i)) +
                              " at [" + std::to_string(j) + "][" + std::to_string(i) + "])");
      }
    }
  }
  if (scale == 0.0) {
    if (strictlyPositive) return parseError(where, key, "matrix is zero, not positive definite");
    return {};
  }
  const Matrix sym = 0.5 * (a + a.transpose());
  Eigen::SelfAdjointEigenSolver<Matrix> eig(sym, Eigen::EigenvaluesOnly);
  const double lowest = eig.eigenvalues()[0];
  if (strictlyPositive ? !(lowest > tol) : !(lowest >= -tol * static_cast<double>(a.rows()))) {
    return parseError(
        where, key,
        std::string(strictlyPositive ? "matrix is not positive definite" : "matrix is not positive semi-definite") +
            " (smallest eigenvalue " + formatNumber(lowest) + ")");
  }
  return {};
}

Result<int> dofIndex(const json& value, const StructuralModel& model, const std::string& where,
                     const std::string& field) {
  if (!value.is_string()) return parseError(where, field, "expected a DOF label such as \"21+Z\"");
  auto dof = parseDof(value.get<std::string>());
  if (!dof) return parseError(where, field, dof.error().message);
  const int index = model.findDof(*dof);
  if (index < 0) return parseError(where, field, "unknown DOF '" + value.get<std::string>() + "' (not in dofs)");
  return index;
}

Result<std::string> elementName(const json& item, const std::string& where, const std::string& field,
                                std::set<std::string>& names) {
  if (!item.contains("name") || !item["name"].is_string() || item["name"].get<std::string>().empty()) {
    return parseError(where, field + ".name", "expected a non-empty string");
  }
  const std::string name = item["name"].get<std::string>();
  if (name == "damping" || name == "stiffness" || name == "mass") {
    return parseError(where, field + ".name",
                      "'" + name + "' is reserved (a parameter acting on it scales the whole " +
                          (name == "damping" ? std::string("damping")
                           : name == "mass"  ? "M"
                                             : "K") +
                          ")");
  }
  if (!names.insert(name).second) return parseError(where, field + ".name", "duplicate element name '" + name + "'");
  return name;
}

// A required member of the element at `field`: the index of its DOF label.
Result<int> requiredDof(const json& item, const char* key, const StructuralModel& model, const std::string& where,
                        const std::string& field) {
  if (!item.contains(key)) return parseError(where, field + "." + key, "missing");
  return dofIndex(item[key], model, where, field + "." + key);
}

// A required member of the element at `field`: a finite positive number.
Result<double> requiredPositive(const json& item, const char* key, const std::string& where, const std::string& field) {
  const std::string member = field + "." + key;
  if (!item.contains(key)) return parseError(where, member, "missing");
  MOZZI_TRY_ASSIGN(const double x, finiteNumber(item[key], where, member));
  if (!(x > 0)) return parseError(where, member, "must be positive");
  return x;
}

// parseObject(item, field) for every object of the optional array root[key]
// ("springs", "masses", "parameters"), field = "key[i]"; the first error stops.
template <class ParseObject>
Result<void> forEachObject(const json& root, const char* key, const std::string& where, ParseObject parseObject) {
  if (!root.contains(key)) return {};
  const json& list = root[key];
  if (!list.is_array()) return parseError(where, key, "expected an array");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string field = std::string(key) + "[" + std::to_string(i) + "]";
    if (!list[i].is_object()) return parseError(where, field, "expected an object");
    MOZZI_TRY(parseObject(list[i], field));
  }
  return {};
}

Result<void> parseElements(const json& root, StructuralModel& model, const std::string& where) {
  std::set<std::string> names;
  MOZZI_TRY(forEachObject(root, "springs", where, [&](const json& s, const std::string& field) -> Result<void> {
    Spring spring;
    MOZZI_TRY_ASSIGN(spring.name, elementName(s, where, field, names));
    MOZZI_TRY_ASSIGN(spring.a, requiredDof(s, "a", model, where, field));
    if (!s.contains("b")) return parseError(where, field + ".b", "missing (a DOF label or \"ground\")");
    if (s["b"].is_string() && s["b"].get<std::string>() == "ground") {
      spring.b = -1;
    } else {
      MOZZI_TRY_ASSIGN(spring.b, dofIndex(s["b"], model, where, field + ".b"));
      if (spring.b == spring.a) return parseError(where, field + ".b", "spring joins a DOF to itself");
    }
    MOZZI_TRY_ASSIGN(spring.stiffness, requiredPositive(s, "stiffness", where, field));
    model.springs.push_back(spring);
    return {};
  }));
  return forEachObject(root, "masses", where, [&](const json& s, const std::string& field) -> Result<void> {
    LumpedMass mass;
    MOZZI_TRY_ASSIGN(mass.name, elementName(s, where, field, names));
    MOZZI_TRY_ASSIGN(mass.dof, requiredDof(s, "dof", model, where, field));
    MOZZI_TRY_ASSIGN(mass.mass, requiredPositive(s, "mass", where, field));
    model.masses.push_back(mass);
    return {};
  });
}

Result<void> parseParameters(const json& root, StructuralModel& model, const std::string& where) {
  std::set<std::string> elements, names;
  for (const auto& s : model.springs) elements.insert(s.name);
  for (const auto& m : model.masses) elements.insert(m.name);
  return forEachObject(root, "parameters", where, [&](const json& p, const std::string& field) -> Result<void> {
    ModelParameter param;
    if (!p.contains("name") || !p["name"].is_string() || p["name"].get<std::string>().empty()) {
      return parseError(where, field + ".name", "expected a non-empty string");
    }
    param.name = p["name"].get<std::string>();
    if (!names.insert(param.name).second) return parseError(where, field + ".name", "duplicate parameter name");
    if (!p.contains("acts_on") || !p["acts_on"].is_array() || p["acts_on"].empty()) {
      return parseError(where, field + ".acts_on",
                        "expected a non-empty array of spring/mass names, \"damping\", \"stiffness\" or \"mass\"");
    }
    for (std::size_t j = 0; j < p["acts_on"].size(); ++j) {
      const json& e = p["acts_on"][j];
      const std::string f = field + ".acts_on[" + std::to_string(j) + "]";
      if (!e.is_string()) return parseError(where, f, "expected a name");
      const std::string name = e.get<std::string>();
      if (name != "damping" && name != "stiffness" && name != "mass" && elements.count(name) == 0) {
        return parseError(where, f, "unknown element '" + name + "' (not a spring or mass name)");
      }
      param.actsOn.push_back(name);
    }
    auto number = [&](const char* key, double fallback, double& out) -> Result<void> {
      if (!p.contains(key)) {
        out = fallback;
        return {};
      }
      MOZZI_TRY_ASSIGN(out, finiteNumber(p[key], where, field + "." + key));
      return {};
    };
    MOZZI_TRY(number("nominal", 1.0, param.nominal));
    if (!p.contains("lower") || !p.contains("upper")) {
      return parseError(where, field, "needs bounds \"lower\" and \"upper\" (scale factors)");
    }
    MOZZI_TRY(number("lower", 0.0, param.lower));
    MOZZI_TRY(number("upper", 0.0, param.upper));
    MOZZI_TRY(number("prior_sigma", 0.0, param.priorSigma));
    if (param.lower < 0) return parseError(where, field + ".lower", "a scale factor cannot be negative");
    if (!(param.lower <= param.nominal && param.nominal <= param.upper && param.lower < param.upper)) {
      return parseError(where, field, "bounds must satisfy lower <= nominal <= upper, lower < upper");
    }
    if (param.priorSigma < 0) return parseError(where, field + ".prior_sigma", "must not be negative");
    model.parameters.push_back(param);
    return {};
  });
}

}  // namespace

int StructuralModel::findDof(const Dof& dof) const {
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    if (dofs[i] == dof) return static_cast<int>(i);
  }
  return -1;
}

std::string modelDofLabel(const Dof& dof) {
  return std::to_string(dof.node) + (dof.negative ? "-" : "+") + directionName(dof.direction);
}

Result<StructuralModel> parseModelJson(std::string_view text, const std::string& where) {
  const json root = json::parse(text.begin(), text.end(), nullptr, false);
  if (root.is_discarded()) return makeError(ErrorCode::ParseError, "not valid JSON", where);
  if (!root.is_object()) return parseError(where, "(top level)", "expected a JSON object");
  if (!root.contains("schema") || !root["schema"].is_string()) {
    return parseError(where, "schema", "missing (expected \"" + std::string(kModelSchema) + "\")");
  }
  if (root["schema"].get<std::string>() != kModelSchema) {
    return makeError(ErrorCode::Unsupported,
                     "schema: '" + root["schema"].get<std::string>() + "' is not " + kModelSchema, where);
  }
  StructuralModel model;
  if (root.contains("name")) {
    if (!root["name"].is_string()) return parseError(where, "name", "expected a string");
    model.name = root["name"].get<std::string>();
  }
  if (!root.contains("dofs") || !root["dofs"].is_array() || root["dofs"].empty()) {
    return parseError(where, "dofs", "expected a non-empty array of DOF labels such as \"21+Z\"");
  }
  const json& dofs = root["dofs"];
  if (dofs.size() > static_cast<std::size_t>(kMaxDofs)) {
    return parseError(where, "dofs", "more than " + std::to_string(kMaxDofs) + " DOFs");
  }
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    const std::string field = "dofs[" + std::to_string(i) + "]";
    if (!dofs[i].is_string()) return parseError(where, field, "expected a DOF label such as \"21+Z\"");
    auto dof = parseDof(dofs[i].get<std::string>());
    if (!dof) return parseError(where, field, dof.error().message);
    if (model.findDof(*dof) >= 0) return parseError(where, field, "repeated DOF '" + dofs[i].get<std::string>() + "'");
    Dof flipped = *dof;
    flipped.negative = !flipped.negative;
    if (model.findDof(flipped) >= 0) {
      return parseError(where, field,
                        "DOF '" + dofs[i].get<std::string>() + "' repeats another with the opposite sign");
    }
    model.dofs.push_back(*dof);
    model.labels.push_back(dofs[i].get<std::string>());
  }
  const int n = model.dofCount();
  for (const char* key : {"M", "K"}) {
    if (!root.contains(key)) return parseError(where, key, "missing");
  }
  MOZZI_TRY_ASSIGN(model.m, squareMatrix(root, "M", n, where));
  MOZZI_TRY_ASSIGN(model.k, squareMatrix(root, "K", n, where));
  MOZZI_TRY(checkSymmetricDefinite(model.m, "M", true, where));
  MOZZI_TRY(checkSymmetricDefinite(model.k, "K", false, where));
  const bool hasC = root.contains("C"), hasModal = root.contains("modal_damping");
  if (hasC == hasModal) return parseError(where, "C", "give exactly one of \"C\" and \"modal_damping\"");
  if (hasC) {
    MOZZI_TRY_ASSIGN(model.c, squareMatrix(root, "C", n, where));
    MOZZI_TRY(checkSymmetricDefinite(model.c, "C", false, where));
  } else {
    const json& z = root["modal_damping"];
    if (!z.is_array() || static_cast<int>(z.size()) != n) {
      return parseError(where, "modal_damping", "expected " + std::to_string(n) + " viscous ratios (one per mode)");
    }
    model.modalDamping.resize(n);
    for (int i = 0; i < n; ++i) {
      const std::string field = "modal_damping[" + std::to_string(i) + "]";
      MOZZI_TRY_ASSIGN(const double x, finiteNumber(z[static_cast<std::size_t>(i)], where, field));
      if (!(x >= 0 && x < 1)) return parseError(where, field, "viscous ratio must be in [0, 1)");
      model.modalDamping[i] = x;
    }
  }
  model.t = Matrix::Identity(n, n);
  MOZZI_TRY(parseElements(root, model, where));
  MOZZI_TRY(parseParameters(root, model, where));
  return model;
}

Result<StructuralModel> readModelFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return makeError(ErrorCode::IoError, "cannot open the model file", path);
  std::ostringstream text;
  text << in.rdbuf();
  return parseModelJson(text.str(), path);
}

Result<std::string> writeModelJson(const StructuralModel& model) {
  if (model.t.rows() != model.t.cols() || !model.t.isIdentity()) {
    return makeError(ErrorCode::Unsupported, "only spatial models (T = identity) can be written as mozzi-model/1",
                     model.name);
  }
  json root;
  root["schema"] = kModelSchema;
  if (!model.name.empty()) root["name"] = model.name;
  root["dofs"] = json::array();
  for (const auto& d : model.dofs) root["dofs"].push_back(modelDofLabel(d));
  auto matrix = [](const Matrix& a) {
    json rows = json::array();
    for (Eigen::Index i = 0; i < a.rows(); ++i) {
      json row = json::array();
      for (Eigen::Index j = 0; j < a.cols(); ++j) row.push_back(a(i, j));
      rows.push_back(row);
    }
    return rows;
  };
  root["M"] = matrix(model.m);
  root["K"] = matrix(model.k);
  if (model.usesModalDamping()) {
    root["modal_damping"] =
        std::vector<double>(model.modalDamping.data(), model.modalDamping.data() + model.modalDamping.size());
  } else {
    root["C"] = matrix(model.c);
  }
  for (const auto& s : model.springs) {
    root["springs"].push_back(
        {{"name", s.name},
         {"a", modelDofLabel(model.dofs[static_cast<std::size_t>(s.a)])},
         {"b", s.grounded() ? std::string("ground") : modelDofLabel(model.dofs[static_cast<std::size_t>(s.b)])},
         {"stiffness", s.stiffness}});
  }
  for (const auto& m : model.masses) {
    root["masses"].push_back(
        {{"name", m.name}, {"dof", modelDofLabel(model.dofs[static_cast<std::size_t>(m.dof)])}, {"mass", m.mass}});
  }
  for (const auto& p : model.parameters) {
    root["parameters"].push_back({{"name", p.name},
                                  {"acts_on", p.actsOn},
                                  {"nominal", p.nominal},
                                  {"lower", p.lower},
                                  {"upper", p.upper},
                                  {"prior_sigma", p.priorSigma}});
  }
  return root.dump(1);
}

Result<StructuralModel> modelFromModalData(const io::uff::ModalData& modal, const std::string& where) {
  const auto nm = modal.frequencyHz.size();
  const auto nd = static_cast<Eigen::Index>(modal.dofs.size());
  if (nm == 0 || nd == 0)
    return makeError(ErrorCode::InvalidArgument, "the modal model has no modes or no DOFs", where);
  if (modal.shapes.rows() != nd || modal.shapes.cols() != nm || modal.dampingRatio.size() != nm ||
      modal.modalMass.size() != nm) {
    return makeError(ErrorCode::InvalidArgument, "mode shapes, damping and modal masses disagree in size", where);
  }
  StructuralModel model;
  model.name = where;
  model.dofs = modal.dofs;
  for (const auto& d : modal.dofs) model.labels.push_back(modelDofLabel(d));
  model.t.resize(nd, nm);
  Vector w2(nm);
  for (Eigen::Index r = 0; r < nm; ++r) {
    const std::string mode = "mode " + std::to_string(r + 1);
    const double f = modal.frequencyHz[r], mm = modal.modalMass[r], z = modal.dampingRatio[r];
    if (!(std::isfinite(f) && f > 0))
      return makeError(ErrorCode::InvalidArgument, "frequency must be positive", where + ", " + mode);
    if (!(std::isfinite(mm) && mm > 0)) {
      return makeError(ErrorCode::Unsupported,
                       "modal mass missing: FRFs need mass-normalised shapes (record 8 of dataset 55)",
                       where + ", " + mode);
    }
    if (!(std::isfinite(z) && z >= 0 && z < 1))
      return makeError(ErrorCode::InvalidArgument, "viscous ratio must be in [0, 1)", where + ", " + mode);
    // Real modes: a complex shape is rotated to its best real line first.
    const ComplexVector col = modal.shapes.col(r);
    Eigen::Index big = 0;
    col.cwiseAbs().maxCoeff(&big);
    const Complex phase = std::abs(col[big]) > 0 ? col[big] / std::abs(col[big]) : Complex(1, 0);
    const Vector real = (col / phase).real();
    if (!real.allFinite() || real.cwiseAbs().maxCoeff() == 0) {
      return makeError(ErrorCode::InvalidArgument, "mode shape is zero or not finite", where + ", " + mode);
    }
    model.t.col(r) = real / std::sqrt(mm);  // phi^T M phi = mm -> unit modal mass
    w2[r] = std::pow(2 * M_PI * f, 2);
  }
  model.m = Matrix::Identity(nm, nm);
  model.k = w2.asDiagonal();
  // Modal damping is assigned by ascending frequency: sort to match.
  std::vector<Eigen::Index> order(static_cast<std::size_t>(nm));
  for (Eigen::Index r = 0; r < nm; ++r) order[static_cast<std::size_t>(r)] = r;
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return w2[a] < w2[b]; });
  model.modalDamping.resize(nm);
  for (Eigen::Index r = 0; r < nm; ++r) model.modalDamping[r] = modal.dampingRatio[order[static_cast<std::size_t>(r)]];
  return model;
}

}  // namespace mozzi::core::gap::structural
