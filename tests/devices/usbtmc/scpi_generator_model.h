#pragma once
// Test model of a two-channel SCPI function generator behaving like a
// Keysight 33522B as its programming guide describes it: commands change the
// state, queries answer in NR3 ("+1.00000000000000E+01"), bad values and
// unknown headers go to the error queue (-222 "Data out of range", -221
// "Settings conflict", -113 "Undefined header"), SYST:ERR? returns them
// oldest first and then +0,"No error". Frequency is kept to 1 uHz and
// amplitude to 0.1 mV, so that a read-back can differ from the request.
// "SILENT?" is a query the model never answers (timeout tests).
// Used by the unit tests (through ModelChannel) and by the umockdev tests
// (behind the emulated USBTMC endpoints).

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "devices/usbtmc/scpi.h"

namespace mozzi::devices::testing {

class ScpiGeneratorModel {
 public:
  struct Channel {
    std::string function = "SIN";
    double frequency = 1000.0, amplitude = 0.1, offset = 0.0, symmetry = 100.0;
    bool output = false, highZ = false;
  };

  std::string idn = "Keysight Technologies,33522B,MY00000001,4.00-1.19-2.00-58-00";
  std::vector<std::string> received;  // every message, newline stripped
  std::map<int, Channel> channels{{1, {}}, {2, {}}};
  std::deque<std::pair<int, std::string>> errors;
  bool generator = true;  // false: an instrument without SOURce/OUTPut commands (a DMM, a scope)

  // The answer to one message, if it is a query that gets one.
  std::optional<std::string> handle(std::string message) {
    while (!message.empty() && (message.back() == '\n' || message.back() == '\r')) message.pop_back();
    received.push_back(message);
    const std::size_t space = message.find(' ');
    const std::string header = message.substr(0, space);
    const std::string arg = space == std::string::npos ? "" : message.substr(space + 1);
    if (header == "*IDN?") return idn;
    if (header == "*OPC?") return std::string("1");
    if (header == "*RST") {
      channels = {{1, {}}, {2, {}}};
      return std::nullopt;
    }
    if (header == "*CLS") {
      errors.clear();
      return std::nullopt;
    }
    if (header == "SILENT?") return std::nullopt;
    if (header == "SYST:ERR?") {
      if (errors.empty()) return std::string("+0,\"No error\"");
      auto e = errors.front();
      errors.pop_front();
      char b[16];
      std::snprintf(b, sizeof b, "%+d", e.first);
      return std::string(b) + ",\"" + e.second + "\"";
    }
    int n = 0;
    std::string rest;
    if (!generator || !split(header, n, rest)) return undefined();
    Channel& ch = channels[n];
    const bool query = !rest.empty() && rest.back() == '?';
    if (query) rest.pop_back();
    if (rest == "OUTP") {
      if (query) return std::string(ch.output ? "1" : "0");
      if (arg == "ON" || arg == "1")
        ch.output = true;
      else if (arg == "OFF" || arg == "0")
        ch.output = false;
      else
        return error(-224, "Illegal parameter value");
      return std::nullopt;
    }
    if (rest == "OUTP:LOAD") {
      if (arg == "INF") ch.highZ = true;
      return std::nullopt;
    }
    if (rest == "FUNC") {
      if (query) return ch.function;
      if (arg == "SIN" || arg == "RAMP" || arg == "DC" || arg == "SQU")
        ch.function = arg;
      else
        return error(-224, "Illegal parameter value");
      return std::nullopt;
    }
    if (rest == "VOLT:UNIT") return std::nullopt;
    if (query) {
      if (rest == "FREQ") return nr3(ch.frequency);
      if (rest == "VOLT") return nr3(ch.amplitude);
      if (rest == "VOLT:OFFS") return nr3(ch.offset);
      if (rest == "FUNC:RAMP:SYMM") return nr3(ch.symmetry);
      return undefined();
    }
    char* end = nullptr;
    const double v = std::strtod(arg.c_str(), &end);
    if (arg.empty() || *end != '\0') return error(-104, "Data type error");
    if (rest == "FREQ") {
      const double maxHz = ch.function == "RAMP" ? 200e3 : 30e6;
      if (v < 1e-6 || v > maxHz) return error(-222, "Data out of range");
      ch.frequency = std::round(v * 1e6) / 1e6;
    } else if (rest == "VOLT") {
      if (v < 2e-3 || v > 20.0) return error(-222, "Data out of range");
      if (std::fabs(ch.offset) + v / 2.0 > 10.0) return error(-221, "Settings conflict");
      ch.amplitude = std::round(v * 1e4) / 1e4;
    } else if (rest == "VOLT:OFFS") {
      if (std::fabs(v) + ch.amplitude / 2.0 > 10.0) return error(-221, "Settings conflict");
      ch.offset = std::round(v * 1e4) / 1e4;
    } else if (rest == "FUNC:RAMP:SYMM") {
      if (v < 0.0 || v > 100.0) return error(-222, "Data out of range");
      ch.symmetry = v;
    } else {
      return undefined();
    }
    return std::nullopt;
  }

  static std::string nr3(double v) {
    char b[40];
    std::snprintf(b, sizeof b, "%+.14E", v);
    return b;
  }

 private:
  // "SOUR2:FREQ" -> 2, "FREQ"; "OUTP1:LOAD" -> 1, "OUTP:LOAD"; "OUTP1" -> 1, "OUTP".
  static bool split(const std::string& header, int& n, std::string& rest) {
    for (const char* prefix : {"SOUR", "OUTP"}) {
      const std::string p = prefix;
      if (header.rfind(p, 0) != 0 || header.size() <= p.size() || header[p.size()] < '1' || header[p.size()] > '2')
        continue;
      n = header[p.size()] - '0';
      const std::string tail = header.substr(p.size() + 1);
      if (p == "SOUR") {
        if (tail.empty() || tail[0] != ':') return false;
        rest = tail.substr(1);
      } else {
        rest = "OUTP" + tail;
      }
      return true;
    }
    return false;
  }
  std::optional<std::string> error(int code, const std::string& text) {
    errors.emplace_back(code, text);
    return std::nullopt;
  }
  std::optional<std::string> undefined() { return error(-113, "Undefined header"); }
};

// The model as a MessageChannel, for tests without USB: answers are queued on
// write and handed out by read; a read with nothing queued times out.
class ModelChannel final : public usbtmc::MessageChannel {
 public:
  explicit ModelChannel(ScpiGeneratorModel& model) : model_(model) {}
  core::Result<void> write(const std::string& message, unsigned) override {
    if (auto a = model_.handle(message)) answers_.push_back(*a + "\n");
    return {};
  }
  core::Result<std::string> read(unsigned timeoutMs) override {
    if (answers_.empty())
      return core::makeError(core::ErrorCode::IoError, "no answer within " + std::to_string(timeoutMs) + " ms",
                             where());
    std::string a = answers_.front();
    answers_.pop_front();
    return a;
  }
  core::Result<void> clear() override {
    answers_.clear();
    ++clears;
    return {};
  }
  std::string where() const override { return "model"; }
  int clears = 0;

 private:
  ScpiGeneratorModel& model_;
  std::deque<std::string> answers_;
};

}  // namespace mozzi::devices::testing
