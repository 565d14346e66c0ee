#include "core/common/result.h"

namespace mozzi::core {

const char* errorCodeName(ErrorCode code) {
  switch (code) {
    case ErrorCode::InvalidArgument: return "invalid argument";
    case ErrorCode::ParseError: return "parse error";
    case ErrorCode::IoError: return "i/o error";
    case ErrorCode::NumericalFailure: return "numerical failure";
    case ErrorCode::NotFound: return "not found";
    case ErrorCode::Unsupported: return "unsupported";
    case ErrorCode::Corrupt: return "corrupt data";
    case ErrorCode::Locked: return "locked";
    case ErrorCode::Cancelled: return "cancelled";
  }
  return "error";
}

std::string Error::describe() const {
  std::string text = errorCodeName(code);
  text += ": ";
  text += message;
  if (!where.empty()) {
    text += " (";
    text += where;
    text += ")";
  }
  return text;
}

}  // namespace mozzi::core
