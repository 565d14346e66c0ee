#pragma once
// USBTMC (USB Test and Measurement Class, rev 1.0, 2003) and its USB488
// subclass (rev 1.0) wire format, without I/O (STYLE 1: libsigrok's
// protocol.c). Layouts checked byte by byte in tests/devices/usbtmc.
//
//  - Interface: class 0xFE, subclass 0x03, protocol 0x01 (USB488; 0x00 plain
//    USBTMC); one Bulk-OUT, one Bulk-IN, an optional Interrupt-IN endpoint.
//  - Every Bulk-OUT transfer starts with a 12-byte header:
//      0 MsgID, 1 bTag (1..255), 2 ~bTag, 3 reserved 0, 4..11 message specific
//    DEV_DEP_MSG_OUT (MsgID 1): 4..7 TransferSize u32 LE (message
//      bytes in this transfer, header and padding excluded), 8 bmTransferAttributes
//      (bit 0 EOM: last transfer of the message), 9..11 reserved; then the data
//      and 0..3 zero bytes so that the transfer is a multiple of 4 bytes.
//    REQUEST_DEV_DEP_MSG_IN (MsgID 2): 4..7 TransferSize u32 LE (most
//      bytes the device may send), 8 bit 1 TermCharEnabled, 9 TermChar.
//  - Bulk-IN DEV_DEP_MSG_IN (MsgID 2): 0 MsgID, 1 bTag of the request,
//    2 ~bTag, 3 reserved, 4..7 TransferSize (data bytes in this transfer),
//    8 bit 0 EOM, bit 1 the last byte is the TermChar; then data and padding.
//    A message longer than one transfer comes as several transfers, each
//    asked for by its own REQUEST_DEV_DEP_MSG_IN; the last has EOM set.
//  - Class requests on the default pipe:
//      INITIATE_ABORT_BULK_OUT 1 (0xA2, wValue bTag, wIndex endpoint, 2 bytes)
//      CHECK_ABORT_BULK_OUT_STATUS 2 (0xA2, wIndex endpoint, 8 bytes)
//      INITIATE_ABORT_BULK_IN 3 (0xA2, wValue bTag, wIndex endpoint, 2 bytes)
//      CHECK_ABORT_BULK_IN_STATUS 4 (0xA2, wIndex endpoint, 8 bytes)
//      INITIATE_CLEAR 5 (0xA1, wIndex interface, 1 byte)
//      CHECK_CLEAR_STATUS 6 (0xA1, wIndex interface, 2 bytes)
//      GET_CAPABILITIES 7 (0xA1, wIndex interface, 0x18 bytes)
//      INDICATOR_PULSE 64 (0xA1, wIndex interface, 1 byte)
//      USB488 READ_STATUS_BYTE 128 (0xA1, wValue bTag 2..127, wIndex interface, 3 bytes)
//    Byte 0 of every answer is a USBTMC_status.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/common/result.h"

namespace mozzi::devices::usbtmc {

constexpr std::uint8_t kInterfaceClass = 0xFE;
constexpr std::uint8_t kInterfaceSubclass = 0x03;
constexpr std::uint8_t kProtocolUsbtmc = 0x00;
constexpr std::uint8_t kProtocolUsb488 = 0x01;
constexpr std::size_t kHeaderBytes = 12;

enum MsgId : std::uint8_t {
  kDevDepMsgOut = 1,
  kRequestDevDepMsgIn = 2,
  kDevDepMsgIn = 2,
  kVendorSpecificOut = 126,
  kRequestVendorSpecificIn = 127,
  kUsb488Trigger = 128,
};

enum ClassRequest : std::uint8_t {
  kInitiateAbortBulkOut = 1,
  kCheckAbortBulkOutStatus = 2,
  kInitiateAbortBulkIn = 3,
  kCheckAbortBulkInStatus = 4,
  kInitiateClear = 5,
  kCheckClearStatus = 6,
  kGetCapabilities = 7,
  kIndicatorPulse = 64,
  kReadStatusByte = 128,  // USB488
};

// USBTMC_status values.
enum class Status : std::uint8_t {
  Success = 0x01,
  Pending = 0x02,
  InterruptInBusy = 0x20,  // USB488
  Failed = 0x80,
  TransferNotInProgress = 0x81,
  SplitNotInProgress = 0x82,
  SplitInProgress = 0x83,
};
// "success", "pending", ..., "unknown status 0x.." for values outside the table.
std::string statusName(std::uint8_t status);

// "INITIATE_CLEAR", ...: class request names for messages.
std::string classRequestName(std::uint8_t request);

// The next bTag after `tag`: 1..255, never 0 (USBTMC 3.2: bTag 0 is invalid).
std::uint8_t nextTag(std::uint8_t tag);

// One DEV_DEP_MSG_OUT transfer: header, `length` bytes, zero padding to 4.
std::vector<std::uint8_t> encodeDevDepMsgOut(std::uint8_t tag, const std::uint8_t* data, std::size_t length, bool eom);
// A whole message split into transfers of at most `maxDataPerTransfer` data
// bytes (EOM on the last), tags taken from `tag` onwards; `tag` is left at the
// last one used. An empty message is one transfer with EOM and no data.
std::vector<std::vector<std::uint8_t>> encodeMessage(std::uint8_t& tag, const std::string& message,
                                                     std::size_t maxDataPerTransfer);
// REQUEST_DEV_DEP_MSG_IN: the device may answer up to `maxBytes` data bytes,
// stopping at `termChar` when one is given.
std::vector<std::uint8_t> encodeRequestDevDepMsgIn(std::uint8_t tag, std::uint32_t maxBytes,
                                                   std::optional<std::uint8_t> termChar = std::nullopt);

// Header of a Bulk-IN DEV_DEP_MSG_IN transfer.
struct BulkInHeader {
  std::uint8_t tag = 0;
  std::uint32_t transferSize = 0;
  bool eom = false;
  bool termChar = false;
};
// Checks MsgID, bTag against `expectedTag`, ~bTag, and TransferSize against
// what the request allowed; the error names the field and both values.
core::Result<BulkInHeader> parseBulkInHeader(const std::uint8_t* bytes, std::size_t length, std::uint8_t expectedTag,
                                             std::uint32_t requestedBytes);

// Collects one response message from the Bulk-IN reads of one or more
// transfers. Usage: expect() after sending each REQUEST_DEV_DEP_MSG_IN, then
// feed() every Bulk-IN read until it says TransferDone (send the next request)
// or MessageDone. A transfer whose data is longer than one read continues in
// the next read without a header.
class ResponseAssembler {
 public:
  enum class Step { NeedMoreData, TransferDone, MessageDone };
  explicit ResponseAssembler(std::size_t maxMessageBytes = std::size_t{1} << 20) : maxMessageBytes_(maxMessageBytes) {}

  void expect(std::uint8_t tag, std::uint32_t requestedBytes);
  core::Result<Step> feed(const std::uint8_t* bytes, std::size_t length);
  const std::vector<std::uint8_t>& message() const { return message_; }
  std::string text() const { return std::string(message_.begin(), message_.end()); }
  int transfers() const { return transfers_; }
  void reset();

 private:
  std::size_t maxMessageBytes_;
  std::vector<std::uint8_t> message_;
  std::uint8_t tag_ = 0;
  std::uint32_t requested_ = 0;
  std::uint32_t remaining_ = 0;  // data bytes of the current transfer still to come
  std::size_t padding_ = 0;      // alignment bytes still allowed after the data
  bool inTransfer_ = false;
  bool expecting_ = false;
  bool eom_ = false;
  int transfers_ = 0;
};

// A control request on the default pipe.
struct ControlSetup {
  std::uint8_t requestType = 0;  // bmRequestType
  std::uint8_t request = 0;      // bRequest
  std::uint16_t value = 0;
  std::uint16_t index = 0;
  std::uint16_t length = 0;  // wLength of the answer
};

ControlSetup initiateAbortBulkOut(std::uint8_t tag, std::uint8_t endpoint);
ControlSetup checkAbortBulkOutStatus(std::uint8_t endpoint);
ControlSetup initiateAbortBulkIn(std::uint8_t tag, std::uint8_t endpoint);
ControlSetup checkAbortBulkInStatus(std::uint8_t endpoint);
ControlSetup initiateClear(std::uint8_t interfaceNumber);
ControlSetup checkClearStatus(std::uint8_t interfaceNumber);
ControlSetup getCapabilities(std::uint8_t interfaceNumber);
ControlSetup indicatorPulse(std::uint8_t interfaceNumber);
// USB488 READ_STATUS_BYTE: `tag` must be 2..127 (USB488 4.3.1).
ControlSetup readStatusByte(std::uint8_t tag, std::uint8_t interfaceNumber);
// The READ_STATUS_BYTE tag after `tag`, cycling 2..127.
std::uint8_t nextStatusTag(std::uint8_t tag);

// Answers of the class requests. Every parser checks the length (the error
// names the request) and returns the status as sent; the caller decides.
struct AbortAnswer {  // INITIATE_ABORT_BULK_OUT/IN
  std::uint8_t status = 0;
  std::uint8_t tag = 0;
};
struct CheckAbortAnswer {  // CHECK_ABORT_BULK_OUT/IN_STATUS
  std::uint8_t status = 0;
  bool bulkInFifoHasData = false;  // IN only: read Bulk-IN again before asking again
  std::uint32_t bytes = 0;         // NBYTES_RXD (OUT) / NBYTES_TXD (IN)
};
struct ClearAnswer {  // INITIATE_CLEAR (1 byte) / CHECK_CLEAR_STATUS (2 bytes)
  std::uint8_t status = 0;
  bool bulkInFifoHasData = false;
};
struct Capabilities {  // GET_CAPABILITIES
  std::uint8_t status = 0;
  std::uint16_t bcdUsbtmc = 0;
  bool indicatorPulse = false, talkOnly = false, listenOnly = false, termChar = false;
  std::uint16_t bcdUsb488 = 0;
  bool usb4882 = false, remoteLocal = false, trigger = false;
  bool scpi = false, sr1 = false, rl1 = false, dt1 = false;
};
struct StatusByteAnswer {  // READ_STATUS_BYTE
  std::uint8_t status = 0;
  std::uint8_t tag = 0;
  std::uint8_t statusByte = 0;  // 0 here when the device sends it on Interrupt-IN
};
struct InterruptNotification {  // USB488 Interrupt-IN, READ_STATUS_BYTE answer
  std::uint8_t tag = 0;
  std::uint8_t statusByte = 0;
};

core::Result<AbortAnswer> parseAbortAnswer(const std::vector<std::uint8_t>& bytes);
core::Result<CheckAbortAnswer> parseCheckAbortAnswer(const std::vector<std::uint8_t>& bytes);
core::Result<ClearAnswer> parseInitiateClearAnswer(const std::vector<std::uint8_t>& bytes);
core::Result<ClearAnswer> parseCheckClearAnswer(const std::vector<std::uint8_t>& bytes);
core::Result<Capabilities> parseCapabilities(const std::vector<std::uint8_t>& bytes);
core::Result<StatusByteAnswer> parseStatusByteAnswer(const std::vector<std::uint8_t>& bytes, std::uint8_t expectedTag);
// bNotify1 = 0x80 | bTag, bNotify2 = status byte.
core::Result<InterruptNotification> parseInterruptNotification(const std::vector<std::uint8_t>& bytes,
                                                               std::uint8_t expectedTag);

}  // namespace mozzi::devices::usbtmc
