#include "app/cli/batch_script.h"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>

#include "app/cli/args.h"

namespace mozzi::cli {
namespace {

using core::ErrorCode;
using core::makeError;
using nlohmann::json;

core::Error structureError(const std::string& message, const std::string& where, const std::string& path) {
  return makeError(ErrorCode::ParseError, message, where + ": " + path);
}

// "line L, column C" of a byte offset (nlohmann counts from 1, past the bad byte).
std::string lineAndColumn(const std::string& text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

core::Result<std::string> stringValue(const json& value, const std::string& where, const std::string& path) {
  if (!value.is_string()) return structureError("expected a string", where, path);
  const auto& s = value.get_ref<const std::string&>();
  if (s.size() > kMaxArgumentLength) {
    return structureError("longer than " + std::to_string(kMaxArgumentLength) + " characters", where, path);
  }
  return s;
}

core::Result<std::map<std::string, std::string>> variables(const json& value, const std::string& where,
                                                           const std::string& path) {
  if (!value.is_object()) return structureError("expected an object of \"name\": \"value\" pairs", where, path);
  static const std::set<std::string> builtIn{"project", "name", "stem", "dir"};
  std::map<std::string, std::string> out;
  for (const auto& [key, v] : value.items()) {
    if (key.empty() || key.find_first_of("{}") != std::string::npos) {
      return structureError("a variable's name must be non-empty and without braces", where, path);
    }
    if (builtIn.count(key)) {
      return structureError("'" + key + "' is a built-in variable and cannot be set", where, path);
    }
    auto s = stringValue(v, where, path + "." + quotedArg(key));
    if (!s) return s.error();
    out.emplace(key, *s);
  }
  return out;
}

core::Result<void> onlyKeys(const json& object, const std::set<std::string>& allowed, const std::string& where,
                            const std::string& path) {
  for (const auto& [key, v] : object.items()) {
    (void)v;
    if (!allowed.count(key)) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
      return structureError("unknown key " + quotedArg(key) + " (expected: " + list + ")", where,
                            path.empty() ? quotedArg(key) : path + "." + quotedArg(key));
    }
  }
  return {};
}

}  // namespace

core::Result<BatchScript> parseBatchScript(const std::string& text, const std::string& where) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    return makeError(ErrorCode::ParseError, "not valid JSON", where + ": " + lineAndColumn(text, e.byte));
  } catch (const json::exception&) {
    // Valid syntax the reader cannot hold, such as a number beyond double's range (found by cli_batch_fuzz).
    return makeError(ErrorCode::ParseError, "not valid JSON: a number out of range", where);
  }
  if (!root.is_object()) return structureError("expected a JSON object", where, "top level");
  if (auto r = onlyKeys(root, {"format", "projects", "vars", "steps"}, where, ""); !r) return r.error();
  if (!root.contains("format") || !root["format"].is_string() || root["format"] != kBatchFormat) {
    return structureError(std::string("expected \"format\": \"") + kBatchFormat + "\"", where, "format");
  }
  BatchScript script;
  if (root.contains("vars")) {
    auto v = variables(root["vars"], where, "vars");
    if (!v) return v.error();
    script.vars = std::move(*v);
  }

  if (!root.contains("projects") || !root["projects"].is_array() || root["projects"].empty()) {
    return structureError("expected a non-empty array of projects", where, "projects");
  }
  if (root["projects"].size() > kMaxBatchProjects) {
    return structureError("more than " + std::to_string(kMaxBatchProjects) + " projects", where, "projects");
  }
  std::set<std::string> seen;
  for (std::size_t i = 0; i < root["projects"].size(); ++i) {
    const json& p = root["projects"][i];
    const std::string path = "projects[" + std::to_string(i) + "]";
    BatchProject project;
    if (p.is_string()) {
      auto file = stringValue(p, where, path);
      if (!file) return file.error();
      project.file = *file;
    } else if (p.is_object()) {
      if (auto r = onlyKeys(p, {"file", "vars"}, where, path); !r) return r.error();
      if (!p.contains("file")) return structureError("a project needs its \"file\"", where, path);
      auto file = stringValue(p["file"], where, path + ".file");
      if (!file) return file.error();
      project.file = *file;
      if (p.contains("vars")) {
        auto v = variables(p["vars"], where, path + ".vars");
        if (!v) return v.error();
        project.vars = std::move(*v);
      }
    } else {
      return structureError("expected a file name or {\"file\": ..., \"vars\": {...}}", where, path);
    }
    if (project.file.empty()) return structureError("empty file name", where, path);
    if (!seen.insert(project.file).second) {
      return structureError("project " + quotedArg(project.file) + " is listed twice", where, path);
    }
    script.projects.push_back(std::move(project));
  }

  if (!root.contains("steps") || !root["steps"].is_array() || root["steps"].empty()) {
    return structureError("expected a non-empty array of steps", where, "steps");
  }
  if (root["steps"].size() > kMaxBatchSteps) {
    return structureError("more than " + std::to_string(kMaxBatchSteps) + " steps", where, "steps");
  }
  for (std::size_t i = 0; i < root["steps"].size(); ++i) {
    const json& s = root["steps"][i];
    const std::string path = "steps[" + std::to_string(i) + "]";
    if (!s.is_object()) return structureError("expected {\"name\": ..., \"run\": [...]}", where, path);
    if (auto r = onlyKeys(s, {"name", "run"}, where, path); !r) return r.error();
    if (!s.contains("run") || !s["run"].is_array() || s["run"].empty()) {
      return structureError("expected \"run\": [\"COMMAND\", \"ARG\", ...]", where, path + ".run");
    }
    BatchStep step;
    for (std::size_t k = 0; k < s["run"].size(); ++k) {
      auto arg = stringValue(s["run"][k], where, path + ".run[" + std::to_string(k) + "]");
      if (!arg) return arg.error();
      step.argv.push_back(*arg);
    }
    step.name = step.argv.front();
    if (s.contains("name")) {
      auto name = stringValue(s["name"], where, path + ".name");
      if (!name) return name.error();
      if (!name->empty()) step.name = *name;
    }
    script.steps.push_back(std::move(step));
  }
  return script;
}

std::map<std::string, std::string> batchVariables(const BatchScript& script, const BatchProject& project) {
  namespace fs = std::filesystem;
  const fs::path file(project.file);
  std::map<std::string, std::string> vars{{"project", project.file},
                                          {"name", file.filename().string()},
                                          {"stem", file.stem().string()},
                                          {"dir", file.has_parent_path() ? file.parent_path().string() : "."}};
  for (const auto& [k, v] : script.vars) vars[k] = v;
  for (const auto& [k, v] : project.vars) vars[k] = v;
  return vars;
}

core::Result<std::vector<std::string>> expandBatchStep(const BatchScript& script, std::size_t index,
                                                       const BatchProject& project) {
  const auto vars = batchVariables(script, project);
  const BatchStep& step = script.steps.at(index);
  std::vector<std::string> out;
  out.reserve(step.argv.size());
  for (std::size_t k = 0; k < step.argv.size(); ++k) {
    const std::string& arg = step.argv[k];
    const std::string where =
        "steps[" + std::to_string(index) + "].run[" + std::to_string(k) + "] for project " + quotedArg(project.file);
    std::string expanded;
    for (std::size_t i = 0; i < arg.size(); ++i) {
      const char c = arg[i];
      if ((c == '{' || c == '}') && i + 1 < arg.size() && arg[i + 1] == c) {
        expanded += c;
        ++i;
        continue;
      }
      if (c == '}') return makeError(ErrorCode::ParseError, "a '}' without its '{' (write '}}' for one)", where);
      if (c != '{') {
        expanded += c;
        continue;
      }
      const auto close = arg.find('}', i + 1);
      if (close == std::string::npos) {
        return makeError(ErrorCode::ParseError, "a '{' without its '}' (write '{{' for one)", where);
      }
      const std::string name = arg.substr(i + 1, close - i - 1);
      const auto it = vars.find(name);
      if (it == vars.end())
        return makeError(ErrorCode::ParseError, "unknown variable " + quotedArg("{" + name + "}"), where);
      expanded += it->second;
      i = close;
    }
    if (expanded.size() > kMaxArgumentLength) {
      return makeError(ErrorCode::ParseError,
                       "longer than " + std::to_string(kMaxArgumentLength) + " characters once expanded", where);
    }
    out.push_back(std::move(expanded));
  }
  return out;
}

}  // namespace mozzi::cli
