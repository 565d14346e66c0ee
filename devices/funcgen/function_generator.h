#pragma once
// A SCPI function generator (the common command set of the Keysight 33500B
// and Rigol DG1000Z series, which most bench generators share):
//   OUTP<n>:LOAD INF            high-impedance load: the amplitude set is the
//                               amplitude at the actuator controller's input
//   SOUR<n>:FUNC SIN|RAMP|DC    SOUR<n>:FUNC:RAMP:SYMM 50 (triangle)
//   SOUR<n>:VOLT:UNIT VPP       SOUR<n>:FREQ <Hz>  SOUR<n>:VOLT <Vpp>
//   SOUR<n>:VOLT:OFFS <V>       OUTP<n> ON|OFF
// Capabilities are data (a profile per known model, a conservative one for
// the rest); settings are validated against them before anything is sent,
// every command is checked against the error queue, and configure() reads
// the setting back so the caller gets what the instrument actually applied.

#include <string>
#include <vector>

#include "core/common/result.h"
#include "devices/usbtmc/scpi.h"

namespace mozzi::devices::funcgen {

enum class Waveform { Sine, Ramp, Dc };
const char* waveformName(Waveform w);     // "sine", "ramp", "dc"
const char* waveformKeyword(Waveform w);  // "SIN", "RAMP", "DC"

struct WaveformRange {
  Waveform waveform = Waveform::Sine;
  double minHz = 0.0;
  double maxHz = 0.0;
};

// Output limits into a high-impedance load, from the vendors' data sheets.
struct GeneratorCapabilities {
  std::string model;  // "Keysight 33500B series (33522B)"
  int channels = 1;
  std::vector<WaveformRange> waveforms;
  double minAmplitudeVpp = 0.0;
  double maxAmplitudeVpp = 0.0;
  double maxPeakV = 0.0;  // |offset| + amplitude / 2
  const WaveformRange* range(Waveform w) const;
};

// The profile for an *IDN? answer; an unknown model gets the conservative
// generic profile (1 channel, 1 mHz to 100 kHz, 10 Vpp, 5 V peak).
GeneratorCapabilities capabilitiesFor(const usbtmc::Identity& identity);
GeneratorCapabilities genericCapabilities();

struct OutputSetting {
  int channel = 1;
  Waveform waveform = Waveform::Sine;
  double frequencyHz = 1.0;   // ignored for DC
  double amplitudeVpp = 0.1;  // ignored for DC
  double offsetV = 0.0;
  double symmetryPercent = 50.0;  // ramp only: 50 = triangle
};

// Checks a setting against the capabilities; the error names the field, the
// value and the limit.
core::Result<OutputSetting> validateSetting(const GeneratorCapabilities& caps, const OutputSetting& setting);

// The SCPI commands that apply `setting`, in the order sent (offset to 0 first
// so that no intermediate state exceeds the peak limit).
std::vector<std::string> settingCommands(const OutputSetting& setting);

class FunctionGenerator {
 public:
  FunctionGenerator(usbtmc::ScpiSession& session, GeneratorCapabilities caps)
      : session_(session), caps_(std::move(caps)) {}
  const GeneratorCapabilities& capabilities() const { return caps_; }
  // Validates, sends every command (each checked on the error queue), reads
  // the setting back and returns it.
  core::Result<OutputSetting> configure(const OutputSetting& setting);
  core::Result<OutputSetting> readSetting(int channel);
  core::Result<void> setOutput(int channel, bool on);

 private:
  usbtmc::ScpiSession& session_;
  GeneratorCapabilities caps_;
};

}  // namespace mozzi::devices::funcgen
