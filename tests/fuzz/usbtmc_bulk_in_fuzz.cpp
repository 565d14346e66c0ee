// libFuzzer target for the USBTMC Bulk-IN parser and the SCPI answer parsers:
// any sequence of Bulk-IN reads must give a message or an Error, never a
// crash, a hang or an allocation beyond the assembler's bound.
// Input framing (tests/fuzz/corpus/usbtmc_bulk_in_fuzz/README.md):
//   byte 0: bTag of the first REQUEST_DEV_DEP_MSG_IN; byte 1: requested
//   TransferSize / 4; then reads as [length byte][length bytes] ...
// Each TransferDone asks for the next transfer with the next bTag, as the
// transport does; the assembled message goes through the *IDN?, SYST:ERR?
// and number parsers, and the raw input through the class-request parsers.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "devices/usbtmc/scpi.h"
#include "devices/usbtmc/usbtmc_protocol.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace mozzi::devices::usbtmc;
  if (size < 2) return 0;
  std::uint8_t tag = data[0];
  const std::uint32_t requested = static_cast<std::uint32_t>(data[1]) * 4;
  ResponseAssembler assembler(4096);  // bound: a hostile device cannot make us allocate more
  assembler.expect(tag, requested);
  std::size_t at = 2;
  bool done = false;
  while (at < size && !done) {
    const std::size_t n = std::min<std::size_t>(data[at], size - at - 1);
    auto step = assembler.feed(data + at + 1, n);
    at += 1 + n;
    if (!step) break;
    if (*step == ResponseAssembler::Step::TransferDone) {
      tag = nextTag(tag);
      assembler.expect(tag, requested);
    }
    done = *step == ResponseAssembler::Step::MessageDone;
  }
  const std::string text = assembler.text();
  (void)parseIdentity(text);
  (void)parseScpiError(text);
  (void)parseScpiNumber(text, "fuzz");
  const std::vector<std::uint8_t> raw(data, data + size);
  (void)parseAbortAnswer(raw);
  (void)parseCheckAbortAnswer(raw);
  (void)parseCheckClearAnswer(raw);
  (void)parseCapabilities(raw);
  (void)parseStatusByteAnswer(raw, data[0]);
  (void)parseInterruptNotification(raw, data[0] & 0x7F);
  return 0;
}
