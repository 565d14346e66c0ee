#include "devices/usbtmc/scpi.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace mozzi::devices::usbtmc {

namespace {

std::string trim(const std::string& s) {
  std::size_t a = 0, b = s.size();
  while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r' || s[a] == '\n')) ++a;
  while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' || s[b - 1] == '\r' || s[b - 1] == '\n')) --b;
  return s.substr(a, b - a);
}

// The answer quoted in messages: at most 60 characters, so a garbage answer
// cannot flood the log.
std::string shown(const std::string& s) {
  return "\"" + (s.size() > 60 ? s.substr(0, 60) + "..." : s) + "\"";
}

core::Error about(const core::Error& e, const std::string& command) {
  return core::makeError(e.code, "\"" + command + "\": " + e.message, e.where);
}

}  // namespace

core::Result<Identity> parseIdentity(const std::string& answer) {
  const std::string a = trim(answer);
  std::vector<std::string> fields;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= a.size(); ++i)
    if (i == a.size() || a[i] == ',') {
      fields.push_back(trim(a.substr(start, i - start)));
      start = i + 1;
    }
  if (fields.size() != 4)
    return core::makeError(core::ErrorCode::ParseError,
                           "*IDN? answer " + shown(a) + " has " + std::to_string(fields.size()) +
                               " fields, IEEE 488.2 gives four (manufacturer,model,serial,firmware)",
                           "*IDN?");
  return Identity{fields[0], fields[1], fields[2], fields[3]};
}

core::Result<ScpiError> parseScpiError(const std::string& answer) {
  const std::string a = trim(answer);
  const std::size_t comma = a.find(',');
  const std::string number = trim(a.substr(0, comma));
  char* end = nullptr;
  errno = 0;
  const long code = number.empty() ? 0 : std::strtol(number.c_str(), &end, 10);
  if (number.empty() || end != number.c_str() + number.size() || errno == ERANGE || code < -32768 || code > 32767)
    return core::makeError(core::ErrorCode::ParseError,
                           "SYST:ERR? answer " + shown(a) + " does not start with an error number", "SYST:ERR?");
  ScpiError e;
  e.code = static_cast<int>(code);
  if (comma != std::string::npos) {
    std::string text = trim(a.substr(comma + 1));
    if (text.size() >= 2 && text.front() == '"' && text.back() == '"') text = text.substr(1, text.size() - 2);
    e.message = text;
  }
  return e;
}

core::Result<double> parseScpiNumber(const std::string& answer, const std::string& query) {
  const std::string a = trim(answer);
  char* end = nullptr;
  const double v = a.empty() ? 0.0 : std::strtod(a.c_str(), &end);
  if (a.empty() || end != a.c_str() + a.size() || !std::isfinite(v))
    return core::makeError(core::ErrorCode::ParseError, "answer " + shown(a) + " is not a number", query);
  return v;
}

core::Result<void> ScpiSession::write(const std::string& command) {
  auto r = channel_.write(command + "\n", timeoutMs_);
  if (!r) return about(r.error(), command);
  return {};
}

core::Result<std::string> ScpiSession::query(const std::string& command, std::optional<unsigned> timeoutMs) {
  if (auto w = write(command); !w) return w.error();
  auto r = channel_.read(timeoutMs.value_or(timeoutMs_));
  if (!r) return about(r.error(), command);
  std::string s = std::move(*r);
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  return s;
}

core::Result<double> ScpiSession::queryNumber(const std::string& command) {
  auto r = query(command);
  if (!r) return r.error();
  return parseScpiNumber(*r, command);
}

core::Result<void> ScpiSession::command(const std::string& command) {
  if (auto w = write(command); !w) return w.error();
  auto errors = drainErrors();
  if (!errors) return about(errors.error(), command);
  if (errors->empty()) return {};
  const ScpiError& first = errors->front();
  std::string more = errors->size() > 1 ? " (and " + std::to_string(errors->size() - 1) + " more)" : "";
  return core::makeError(
      core::ErrorCode::InvalidArgument,
      "the instrument rejected \"" + command + "\": " + std::to_string(first.code) + ", " + first.message + more,
      channel_.where());
}

core::Result<Identity> ScpiSession::identify() {
  auto r = query("*IDN?");
  if (!r) return r.error();
  auto id = parseIdentity(*r);
  if (!id) return core::makeError(id.error().code, id.error().message, channel_.where());
  return id;
}

core::Result<void> ScpiSession::reset() {
  if (auto w = write("*RST"); !w) return w;
  return waitComplete();
}

core::Result<void> ScpiSession::clearStatus() {
  return write("*CLS");
}

core::Result<void> ScpiSession::waitComplete(std::optional<unsigned> timeoutMs) {
  auto r = query("*OPC?", timeoutMs);
  if (!r) return r.error();
  auto v = parseScpiNumber(*r, "*OPC?");
  if (!v || *v != 1.0)
    return core::makeError(core::ErrorCode::ParseError, "\"*OPC?\": answer \"" + *r + "\", expected 1",
                           channel_.where());
  return {};
}

core::Result<std::vector<ScpiError>> ScpiSession::drainErrors(int maxEntries) {
  std::vector<ScpiError> errors;
  for (int i = 0; i < maxEntries; ++i) {
    auto r = query("SYST:ERR?");
    if (!r) return r.error();
    auto e = parseScpiError(*r);
    if (!e) return core::makeError(e.error().code, e.error().message, channel_.where());
    if (e->code == 0) return errors;
    errors.push_back(*e);
  }
  return core::makeError(core::ErrorCode::IoError,
                         "the error queue did not empty after " + std::to_string(maxEntries) + " reads of SYST:ERR?",
                         channel_.where());
}

}  // namespace mozzi::devices::usbtmc
