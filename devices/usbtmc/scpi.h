#pragma once
// SCPI on a message transport (IEEE 488.2 / SCPI 1999): commands and queries
// as newline-terminated messages, the common commands (*IDN?, *RST, *CLS,
// *OPC?) and the error queue (SYST:ERR?) drained after each checked command,
// so that an instrument's rejection comes back as an Error naming the command.
// The transport is abstract: UsbtmcTransport in production, a scripted one in
// the unit tests.

#include <optional>
#include <string>
#include <vector>

#include "core/common/result.h"

namespace mozzi::devices::usbtmc {

// A device-dependent message channel (USBTMC Bulk-OUT/IN, or a fake).
class MessageChannel {
 public:
  virtual ~MessageChannel() = default;
  // Sends one whole message; on timeout the transport aborts the transfer.
  virtual core::Result<void> write(const std::string& message, unsigned timeoutMs) = 0;
  // Reads one whole response message; on timeout the transport aborts the request.
  virtual core::Result<std::string> read(unsigned timeoutMs) = 0;
  // Device clear (IEEE 488.1 SDC): empties the instrument's input and output.
  virtual core::Result<void> clear() = 0;
  // Where errors happen, e.g. "usbtmc usb:1.5".
  virtual std::string where() const = 0;
};

// *IDN? answer: four comma-separated fields (IEEE 488.2 4.1.3.6).
struct Identity {
  std::string manufacturer, model, serial, firmware;
};
core::Result<Identity> parseIdentity(const std::string& answer);

// One entry of the SCPI error queue: <code>,"<message>" (SCPI 21.8.8).
struct ScpiError {
  int code = 0;
  std::string message;
};
core::Result<ScpiError> parseScpiError(const std::string& answer);

// A number in a SCPI response (NR1/NR2/NR3, e.g. "+1.00000000000000E+01").
core::Result<double> parseScpiNumber(const std::string& answer, const std::string& query);

class ScpiSession {
 public:
  explicit ScpiSession(MessageChannel& channel, unsigned timeoutMs = 2000) : channel_(channel), timeoutMs_(timeoutMs) {}

  unsigned timeoutMs() const { return timeoutMs_; }
  void setTimeoutMs(unsigned ms) { timeoutMs_ = ms; }

  // Sends `command` with its newline; no error-queue check.
  core::Result<void> write(const std::string& command);
  // Sends `command` and reads the answer without its trailing newline. A
  // timeout gives an Error naming the query.
  core::Result<std::string> query(const std::string& command, std::optional<unsigned> timeoutMs = std::nullopt);
  core::Result<double> queryNumber(const std::string& command);
  // Sends `command`, then drains the error queue: an Error naming the command
  // and the instrument's first error when it complained.
  core::Result<void> command(const std::string& command);

  core::Result<Identity> identify();
  // *RST then *OPC?: the instrument is in its default state when this returns.
  core::Result<void> reset();
  core::Result<void> clearStatus();                                                   // *CLS
  core::Result<void> waitComplete(std::optional<unsigned> timeoutMs = std::nullopt);  // *OPC? == 1
  // Reads SYST:ERR? until "0,..." (at most `maxEntries`, so a broken
  // instrument cannot keep us here); the errors found, oldest first.
  core::Result<std::vector<ScpiError>> drainErrors(int maxEntries = 32);

 private:
  MessageChannel& channel_;
  unsigned timeoutMs_;
};

}  // namespace mozzi::devices::usbtmc
