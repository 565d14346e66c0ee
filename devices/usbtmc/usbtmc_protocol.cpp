#include "devices/usbtmc/usbtmc_protocol.h"

#include <algorithm>
#include <cstdio>

namespace mozzi::devices::usbtmc {

namespace {

constexpr std::uint8_t kClassInInterface = 0xA1;  // device-to-host, class, interface
constexpr std::uint8_t kClassInEndpoint = 0xA2;   // device-to-host, class, endpoint

std::string hex2(unsigned v) {
  char b[8];
  std::snprintf(b, sizeof b, "0x%02X", v & 0xFFu);
  return b;
}

void putU32(std::vector<std::uint8_t>& out, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
}

std::uint32_t getU32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

std::vector<std::uint8_t> header(std::uint8_t msgId, std::uint8_t tag) {
  std::vector<std::uint8_t> h(kHeaderBytes, 0);
  h[0] = msgId;
  h[1] = tag;
  h[2] = static_cast<std::uint8_t>(~tag);
  return h;
}

core::Result<void> needBytes(const std::vector<std::uint8_t>& bytes, std::size_t n, const char* request) {
  if (bytes.size() >= n) return {};
  return core::makeError(core::ErrorCode::ParseError,
                         "answer of " + std::string(request) + " has " + std::to_string(bytes.size()) +
                             " bytes, the request needs " + std::to_string(n),
                         "usbtmc control");
}

}  // namespace

std::string statusName(std::uint8_t status) {
  switch (static_cast<Status>(status)) {
    case Status::Success: return "success";
    case Status::Pending: return "pending";
    case Status::InterruptInBusy: return "interrupt-in busy";
    case Status::Failed: return "failed";
    case Status::TransferNotInProgress: return "transfer not in progress";
    case Status::SplitNotInProgress: return "split not in progress";
    case Status::SplitInProgress: return "split in progress";
  }
  return "unknown status " + hex2(status);
}

std::string classRequestName(std::uint8_t request) {
  switch (request) {
    case kInitiateAbortBulkOut: return "INITIATE_ABORT_BULK_OUT";
    case kCheckAbortBulkOutStatus: return "CHECK_ABORT_BULK_OUT_STATUS";
    case kInitiateAbortBulkIn: return "INITIATE_ABORT_BULK_IN";
    case kCheckAbortBulkInStatus: return "CHECK_ABORT_BULK_IN_STATUS";
    case kInitiateClear: return "INITIATE_CLEAR";
    case kCheckClearStatus: return "CHECK_CLEAR_STATUS";
    case kGetCapabilities: return "GET_CAPABILITIES";
    case kIndicatorPulse: return "INDICATOR_PULSE";
    case kReadStatusByte: return "READ_STATUS_BYTE";
  }
  return "class request " + hex2(request);
}

std::uint8_t nextTag(std::uint8_t tag) {
  return tag == 255 ? 1 : static_cast<std::uint8_t>(tag + 1);
}

std::uint8_t nextStatusTag(std::uint8_t tag) {
  return tag < 2 || tag >= 127 ? 2 : static_cast<std::uint8_t>(tag + 1);
}

std::vector<std::uint8_t> encodeDevDepMsgOut(std::uint8_t tag, const std::uint8_t* data, std::size_t length, bool eom) {
  std::vector<std::uint8_t> out = header(kDevDepMsgOut, tag);
  putU32(out, 4, static_cast<std::uint32_t>(length));
  out[8] = eom ? 0x01 : 0x00;
  if (length > 0) out.insert(out.end(), data, data + length);
  out.resize((out.size() + 3) / 4 * 4, 0);  // alignment bytes: the transfer is a multiple of 4
  return out;
}

std::vector<std::vector<std::uint8_t>> encodeMessage(std::uint8_t& tag, const std::string& message,
                                                     std::size_t maxDataPerTransfer) {
  const std::size_t chunk = std::max<std::size_t>(maxDataPerTransfer, 1);
  const auto* p = reinterpret_cast<const std::uint8_t*>(message.data());
  std::vector<std::vector<std::uint8_t>> transfers;
  std::size_t at = 0;
  do {
    const std::size_t n = std::min(chunk, message.size() - at);
    tag = nextTag(tag);
    transfers.push_back(encodeDevDepMsgOut(tag, p + at, n, at + n == message.size()));
    at += n;
  } while (at < message.size());
  return transfers;
}

std::vector<std::uint8_t> encodeRequestDevDepMsgIn(std::uint8_t tag, std::uint32_t maxBytes,
                                                   std::optional<std::uint8_t> termChar) {
  std::vector<std::uint8_t> out = header(kRequestDevDepMsgIn, tag);
  putU32(out, 4, maxBytes);
  if (termChar) {
    out[8] = 0x02;
    out[9] = *termChar;
  }
  return out;
}

core::Result<BulkInHeader> parseBulkInHeader(const std::uint8_t* bytes, std::size_t length, std::uint8_t expectedTag,
                                             std::uint32_t requestedBytes) {
  const char* where = "usbtmc bulk-in";
  if (length < kHeaderBytes)
    return core::makeError(
        core::ErrorCode::ParseError,
        "Bulk-IN transfer of " + std::to_string(length) + " bytes is shorter than the 12-byte header", where);
  if (bytes[0] != kDevDepMsgIn)
    return core::makeError(core::ErrorCode::ParseError,
                           "Bulk-IN MsgID is " + hex2(bytes[0]) + ", expected DEV_DEP_MSG_IN (0x02)", where);
  if (static_cast<std::uint8_t>(bytes[1] ^ bytes[2]) != 0xFF)
    return core::makeError(core::ErrorCode::ParseError,
                           "Bulk-IN bTagInverse " + hex2(bytes[2]) + " is not the complement of bTag " + hex2(bytes[1]),
                           where);
  if (bytes[1] != expectedTag)
    return core::makeError(core::ErrorCode::ParseError,
                           "Bulk-IN bTag " + hex2(bytes[1]) + " does not match the request's bTag " + hex2(expectedTag),
                           where);
  BulkInHeader h;
  h.tag = bytes[1];
  h.transferSize = getU32(bytes + 4);
  h.eom = (bytes[8] & 0x01) != 0;
  h.termChar = (bytes[8] & 0x02) != 0;
  if (h.transferSize > requestedBytes)
    return core::makeError(core::ErrorCode::ParseError,
                           "Bulk-IN TransferSize " + std::to_string(h.transferSize) + " exceeds the " +
                               std::to_string(requestedBytes) + " bytes requested",
                           where);
  return h;
}

void ResponseAssembler::reset() {
  message_.clear();
  inTransfer_ = expecting_ = eom_ = false;
  remaining_ = 0;
  padding_ = 0;
  transfers_ = 0;
}

void ResponseAssembler::expect(std::uint8_t tag, std::uint32_t requestedBytes) {
  tag_ = tag;
  requested_ = requestedBytes;
  expecting_ = true;
  inTransfer_ = false;
}

core::Result<ResponseAssembler::Step> ResponseAssembler::feed(const std::uint8_t* bytes, std::size_t length) {
  const char* where = "usbtmc bulk-in";
  std::size_t at = 0;
  if (!inTransfer_) {
    if (!expecting_)
      return core::makeError(core::ErrorCode::ParseError, "Bulk-IN data arrived without a REQUEST_DEV_DEP_MSG_IN",
                             where);
    auto h = parseBulkInHeader(bytes, length, tag_, requested_);
    if (!h) return h.error();
    if (h->transferSize == 0 && !h->eom && !h->termChar)
      // Would make the host ask forever: the device has nothing and says more follows.
      return core::makeError(core::ErrorCode::ParseError, "empty Bulk-IN transfer without EOM", where);
    if (message_.size() + h->transferSize > maxMessageBytes_)
      return core::makeError(core::ErrorCode::ParseError,
                             "response longer than " + std::to_string(maxMessageBytes_) + " bytes", where);
    expecting_ = false;
    inTransfer_ = true;
    remaining_ = h->transferSize;
    padding_ = (4 - (kHeaderBytes + h->transferSize) % 4) % 4;
    eom_ = h->eom || h->termChar;
    ++transfers_;
    at = kHeaderBytes;
  } else if (length == 0) {
    return core::makeError(core::ErrorCode::ParseError,
                           "Bulk-IN transfer ended " + std::to_string(remaining_) + " bytes short of its TransferSize",
                           where);
  }
  const std::size_t take = std::min<std::size_t>(remaining_, length - at);
  message_.insert(message_.end(), bytes + at, bytes + at + take);
  remaining_ -= static_cast<std::uint32_t>(take);
  at += take;
  const std::size_t extra = length - at;
  if (remaining_ > 0) return Step::NeedMoreData;
  if (extra > padding_)
    return core::makeError(core::ErrorCode::ParseError,
                           "Bulk-IN transfer carries " + std::to_string(extra) + " bytes after its TransferSize",
                           where);
  inTransfer_ = false;
  return eom_ ? Step::MessageDone : Step::TransferDone;
}

ControlSetup initiateAbortBulkOut(std::uint8_t tag, std::uint8_t endpoint) {
  return {kClassInEndpoint, kInitiateAbortBulkOut, tag, endpoint, 2};
}
ControlSetup checkAbortBulkOutStatus(std::uint8_t endpoint) {
  return {kClassInEndpoint, kCheckAbortBulkOutStatus, 0, endpoint, 8};
}
ControlSetup initiateAbortBulkIn(std::uint8_t tag, std::uint8_t endpoint) {
  return {kClassInEndpoint, kInitiateAbortBulkIn, tag, endpoint, 2};
}
ControlSetup checkAbortBulkInStatus(std::uint8_t endpoint) {
  return {kClassInEndpoint, kCheckAbortBulkInStatus, 0, endpoint, 8};
}
ControlSetup initiateClear(std::uint8_t interfaceNumber) {
  return {kClassInInterface, kInitiateClear, 0, interfaceNumber, 1};
}
ControlSetup checkClearStatus(std::uint8_t interfaceNumber) {
  return {kClassInInterface, kCheckClearStatus, 0, interfaceNumber, 2};
}
ControlSetup getCapabilities(std::uint8_t interfaceNumber) {
  return {kClassInInterface, kGetCapabilities, 0, interfaceNumber, 0x18};
}
ControlSetup indicatorPulse(std::uint8_t interfaceNumber) {
  return {kClassInInterface, kIndicatorPulse, 0, interfaceNumber, 1};
}
ControlSetup readStatusByte(std::uint8_t tag, std::uint8_t interfaceNumber) {
  return {kClassInInterface, kReadStatusByte, tag, interfaceNumber, 3};
}

core::Result<AbortAnswer> parseAbortAnswer(const std::vector<std::uint8_t>& bytes) {
  if (auto r = needBytes(bytes, 2, "INITIATE_ABORT_BULK_OUT/IN"); !r) return r.error();
  return AbortAnswer{bytes[0], bytes[1]};
}

core::Result<CheckAbortAnswer> parseCheckAbortAnswer(const std::vector<std::uint8_t>& bytes) {
  if (auto r = needBytes(bytes, 8, "CHECK_ABORT_BULK_OUT/IN_STATUS"); !r) return r.error();
  return CheckAbortAnswer{bytes[0], (bytes[1] & 0x01) != 0, getU32(bytes.data() + 4)};
}

core::Result<ClearAnswer> parseInitiateClearAnswer(const std::vector<std::uint8_t>& bytes) {
  if (auto r = needBytes(bytes, 1, "INITIATE_CLEAR"); !r) return r.error();
  return ClearAnswer{bytes[0], false};
}

core::Result<ClearAnswer> parseCheckClearAnswer(const std::vector<std::uint8_t>& bytes) {
  if (auto r = needBytes(bytes, 2, "CHECK_CLEAR_STATUS"); !r) return r.error();
  return ClearAnswer{bytes[0], (bytes[1] & 0x01) != 0};
}

core::Result<Capabilities> parseCapabilities(const std::vector<std::uint8_t>& bytes) {
  if (auto r = needBytes(bytes, 0x18, "GET_CAPABILITIES"); !r) return r.error();
  Capabilities c;
  c.status = bytes[0];
  c.bcdUsbtmc = static_cast<std::uint16_t>(bytes[2] | bytes[3] << 8);
  c.indicatorPulse = (bytes[4] & 0x04) != 0;
  c.talkOnly = (bytes[4] & 0x02) != 0;
  c.listenOnly = (bytes[4] & 0x01) != 0;
  c.termChar = (bytes[5] & 0x01) != 0;
  c.bcdUsb488 = static_cast<std::uint16_t>(bytes[12] | bytes[13] << 8);
  c.usb4882 = (bytes[14] & 0x04) != 0;
  c.remoteLocal = (bytes[14] & 0x02) != 0;
  c.trigger = (bytes[14] & 0x01) != 0;
  c.scpi = (bytes[15] & 0x08) != 0;
  c.sr1 = (bytes[15] & 0x04) != 0;
  c.rl1 = (bytes[15] & 0x02) != 0;
  c.dt1 = (bytes[15] & 0x01) != 0;
  return c;
}

core::Result<StatusByteAnswer> parseStatusByteAnswer(const std::vector<std::uint8_t>& bytes, std::uint8_t expectedTag) {
  if (auto r = needBytes(bytes, 3, "READ_STATUS_BYTE"); !r) return r.error();
  if (bytes[1] != expectedTag)
    return core::makeError(core::ErrorCode::ParseError,
                           "READ_STATUS_BYTE answered bTag " + hex2(bytes[1]) + ", expected " + hex2(expectedTag),
                           "usbtmc control");
  return StatusByteAnswer{bytes[0], bytes[1], bytes[2]};
}

core::Result<InterruptNotification> parseInterruptNotification(const std::vector<std::uint8_t>& bytes,
                                                               std::uint8_t expectedTag) {
  if (bytes.size() < 2)
    return core::makeError(core::ErrorCode::ParseError, "Interrupt-IN notification shorter than 2 bytes",
                           "usbtmc interrupt-in");
  if ((bytes[0] & 0x80) == 0 || (bytes[0] & 0x7F) != expectedTag)
    return core::makeError(core::ErrorCode::ParseError,
                           "Interrupt-IN bNotify1 " + hex2(bytes[0]) + " is not 0x80 | bTag " + hex2(expectedTag),
                           "usbtmc interrupt-in");
  return InterruptNotification{static_cast<std::uint8_t>(bytes[0] & 0x7F), bytes[1]};
}

}  // namespace mozzi::devices::usbtmc
