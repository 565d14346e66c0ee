#include "devices/funcgen/function_generator.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/common/text.h"

namespace mozzi::devices::funcgen {

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// Numbers as sent: enough digits for the instruments' resolution (the 33500B
// sets frequency to 1 uHz), no locale.
std::string scpiNumber(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

core::Error outOfRange(const std::string& field, double value, const std::string& unit, double lo, double hi,
                       const std::string& model) {
  return core::makeError(core::ErrorCode::InvalidArgument,
                         field + " " + core::formatNumber(value, 6) + " " + unit + " is outside " +
                             core::formatNumber(lo, 6) + " .. " + core::formatNumber(hi, 6) + " " + unit + " of the " +
                             model,
                         field);
}

std::string source(int channel) {
  return "SOUR" + std::to_string(channel);
}

}  // namespace

const char* waveformName(Waveform w) {
  switch (w) {
    case Waveform::Sine: return "sine";
    case Waveform::Ramp: return "ramp";
    case Waveform::Dc: return "dc";
  }
  return "unknown";
}

const char* waveformKeyword(Waveform w) {
  switch (w) {
    case Waveform::Sine: return "SIN";
    case Waveform::Ramp: return "RAMP";
    case Waveform::Dc: return "DC";
  }
  return "SIN";
}

const WaveformRange* GeneratorCapabilities::range(Waveform w) const {
  for (const auto& r : waveforms)
    if (r.waveform == w) return &r;
  return nullptr;
}

GeneratorCapabilities genericCapabilities() {
  // Limits every bench generator of this class meets (the smallest of the
  // common ones: 10 Vpp, +/-5 V, 100 kHz), so that an unknown model is never
  // asked for more than it can do; the actuator needs 45 Hz and 10 V at most.
  GeneratorCapabilities c;
  c.model = "SCPI function generator (generic profile)";
  c.channels = 1;
  c.waveforms = {{Waveform::Sine, 1e-3, 100e3}, {Waveform::Ramp, 1e-3, 100e3}, {Waveform::Dc, 0.0, 0.0}};
  c.minAmplitudeVpp = 0.01;
  c.maxAmplitudeVpp = 10.0;
  c.maxPeakV = 5.0;
  return c;
}

GeneratorCapabilities capabilitiesFor(const usbtmc::Identity& identity) {
  const std::string maker = upper(identity.manufacturer);
  const std::string model = upper(identity.model);
  const bool keysight = maker.find("KEYSIGHT") != std::string::npos || maker.find("AGILENT") != std::string::npos;
  if (keysight && model.size() == 6 && model.rfind("335", 0) == 0 && model[5] == 'B') {
    // 33500B data sheet: 33509B..33512B 20 MHz, 33519B..33522B 30 MHz sine,
    // last digit 0 or 2: two channels; ramp/triangle 200 kHz;
    // into an open circuit 2 mVpp .. 20 Vpp, |offset| + Vpp/2 <= 10 V.
    GeneratorCapabilities c;
    c.model = "Keysight 33500B series (" + identity.model + ")";
    const int number = std::atoi(model.c_str());
    c.channels = (number % 10 == 0 || number % 10 == 2) ? 2 : 1;
    const double sineMax = number >= 33519 ? 30e6 : 20e6;
    c.waveforms = {{Waveform::Sine, 1e-6, sineMax}, {Waveform::Ramp, 1e-6, 200e3}, {Waveform::Dc, 0.0, 0.0}};
    c.minAmplitudeVpp = 2e-3;
    c.maxAmplitudeVpp = 20.0;
    c.maxPeakV = 10.0;
    return c;
  }
  if (maker.find("RIGOL") != std::string::npos && model.rfind("DG10", 0) == 0 && model.back() == 'Z') {
    // DG1000Z data sheet: two channels; DG1022Z 25 MHz, DG1032Z 30 MHz,
    // DG1062Z 60 MHz sine; ramp 500 kHz; HighZ 2 mVpp .. 20 Vpp, peak 10 V.
    GeneratorCapabilities c;
    c.model = "Rigol DG1000Z series (" + identity.model + ")";
    c.channels = 2;
    const double sineMax = model == "DG1062Z" ? 60e6 : model == "DG1032Z" ? 30e6 : 25e6;
    c.waveforms = {{Waveform::Sine, 1e-6, sineMax}, {Waveform::Ramp, 1e-6, 500e3}, {Waveform::Dc, 0.0, 0.0}};
    c.minAmplitudeVpp = 2e-3;
    c.maxAmplitudeVpp = 20.0;
    c.maxPeakV = 10.0;
    return c;
  }
  GeneratorCapabilities c = genericCapabilities();
  c.model = identity.manufacturer + " " + identity.model + " (generic profile)";
  return c;
}

core::Result<OutputSetting> validateSetting(const GeneratorCapabilities& caps, const OutputSetting& s) {
  if (s.channel < 1 || s.channel > caps.channels)
    return outOfRange("channel", s.channel, "", 1, caps.channels, caps.model);
  const WaveformRange* range = caps.range(s.waveform);
  if (!range)
    return core::makeError(core::ErrorCode::Unsupported,
                           std::string("waveform ") + waveformName(s.waveform) + " is not offered by the " + caps.model,
                           "waveform");
  for (double v : {s.frequencyHz, s.amplitudeVpp, s.offsetV, s.symmetryPercent})
    if (!std::isfinite(v))
      return core::makeError(core::ErrorCode::InvalidArgument, "a setting is not a finite number", "setting");
  OutputSetting out = s;
  double peak = std::fabs(s.offsetV);
  if (s.waveform != Waveform::Dc) {
    if (s.frequencyHz < range->minHz || s.frequencyHz > range->maxHz)
      return outOfRange("frequency", s.frequencyHz, "Hz", range->minHz, range->maxHz, caps.model);
    if (s.amplitudeVpp < caps.minAmplitudeVpp || s.amplitudeVpp > caps.maxAmplitudeVpp)
      return outOfRange("amplitude", s.amplitudeVpp, "Vpp", caps.minAmplitudeVpp, caps.maxAmplitudeVpp, caps.model);
    if (s.waveform == Waveform::Ramp && (s.symmetryPercent < 0.0 || s.symmetryPercent > 100.0))
      return outOfRange("symmetry", s.symmetryPercent, "%", 0.0, 100.0, caps.model);
    peak += s.amplitudeVpp / 2.0;
  } else {
    out.frequencyHz = 0.0;
    out.amplitudeVpp = 0.0;
  }
  if (peak > caps.maxPeakV)
    return core::makeError(core::ErrorCode::InvalidArgument,
                           "offset " + core::formatNumber(s.offsetV) + " V with amplitude " +
                               core::formatNumber(out.amplitudeVpp) + " Vpp reaches " + core::formatNumber(peak) +
                               " V, beyond the " + core::formatNumber(caps.maxPeakV) + " V peak of the " + caps.model,
                           "offset");
  return out;
}

std::vector<std::string> settingCommands(const OutputSetting& s) {
  const std::string src = source(s.channel);
  std::vector<std::string> c = {"OUTP" + std::to_string(s.channel) + ":LOAD INF", src + ":VOLT:OFFS 0",
                                src + ":FUNC " + waveformKeyword(s.waveform)};
  if (s.waveform == Waveform::Ramp) c.push_back(src + ":FUNC:RAMP:SYMM " + scpiNumber(s.symmetryPercent));
  if (s.waveform != Waveform::Dc) {
    c.push_back(src + ":VOLT:UNIT VPP");
    c.push_back(src + ":FREQ " + scpiNumber(s.frequencyHz));
    c.push_back(src + ":VOLT " + scpiNumber(s.amplitudeVpp));
  }
  c.push_back(src + ":VOLT:OFFS " + scpiNumber(s.offsetV));
  return c;
}

core::Result<OutputSetting> FunctionGenerator::readSetting(int channel) {
  const std::string src = source(channel);
  auto func = session_.query(src + ":FUNC?");
  if (!func) return func.error();
  OutputSetting s;
  s.channel = channel;
  const std::string f = upper(*func);
  // Long and short forms: SIN/SINUSOID, RAMP, DC.
  if (f.rfind("SIN", 0) == 0)
    s.waveform = Waveform::Sine;
  else if (f.rfind("RAMP", 0) == 0)
    s.waveform = Waveform::Ramp;
  else if (f == "DC")
    s.waveform = Waveform::Dc;
  else
    return core::makeError(core::ErrorCode::Unsupported, "the instrument reports function \"" + *func + "\"",
                           src + ":FUNC?");
  auto offset = session_.queryNumber(src + ":VOLT:OFFS?");
  if (!offset) return offset.error();
  s.offsetV = *offset;
  if (s.waveform == Waveform::Dc) {
    s.frequencyHz = s.amplitudeVpp = 0.0;
    return s;
  }
  auto freq = session_.queryNumber(src + ":FREQ?");
  if (!freq) return freq.error();
  auto volt = session_.queryNumber(src + ":VOLT?");
  if (!volt) return volt.error();
  s.frequencyHz = *freq;
  s.amplitudeVpp = *volt;
  if (s.waveform == Waveform::Ramp) {
    auto symm = session_.queryNumber(src + ":FUNC:RAMP:SYMM?");
    if (!symm) return symm.error();
    s.symmetryPercent = *symm;
  }
  return s;
}

core::Result<OutputSetting> FunctionGenerator::configure(const OutputSetting& setting) {
  auto valid = validateSetting(caps_, setting);
  if (!valid) return valid.error();
  for (const auto& c : settingCommands(*valid))
    if (auto r = session_.command(c); !r) return r.error();
  return readSetting(valid->channel);
}

core::Result<void> FunctionGenerator::setOutput(int channel, bool on) {
  if (channel < 1 || channel > caps_.channels)
    return outOfRange("channel", channel, "", 1, caps_.channels, caps_.model);
  return session_.command("OUTP" + std::to_string(channel) + (on ? " ON" : " OFF"));
}

}  // namespace mozzi::devices::funcgen
