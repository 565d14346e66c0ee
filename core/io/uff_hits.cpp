#include "core/io/uff_hits.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <utility>

#include "core/io/uff/uff.h"

namespace mozzi::core::io {

namespace {
namespace sg = core::signal;

// UFF record 9 specific data type -> transducer kind (8 displacement,
// 11 velocity, 12 acceleration, 13 excitation force).
sg::TransducerKind kindFromUff(int specificDataType) {
  switch (specificDataType) {
    case 8: return sg::TransducerKind::Displacement;
    case 11: return sg::TransducerKind::Velocity;
    case 12: return sg::TransducerKind::Acceleration;
    case 13: return sg::TransducerKind::Force;
    default: return sg::TransducerKind::Other;
  }
}
}  // namespace

struct UffHitReader::Impl {
  std::string path;
  std::vector<Dof> references;
  std::optional<uff::DatasetReader> reader;
  // Four buffers in turn: the hit being read (a hit ends where the next load
  // case's first record starts, which is read into the following buffer), the
  // one handed out last and the one before it, which a consumer may still be
  // working on while the next hit is read (the header's contract; `mozzi-cli
  // frf` averages hits k and k + 1 on a second thread while it reads and
  // checks hit k + 2).
  static constexpr int kBuffers = 4;
  UffHit hits[kBuffers];
  Eigen::Index count[kBuffers] = {};  // channels written into each buffer
  int filling = 0;                    // buffer of the hit being read
  std::set<int> finished;             // load cases handed out
  bool any = false, ended = false;
  std::function<void(Eigen::Index)> onFirstLength;  // called once, then cleared
  // what the sink did with the last record
  bool sinkUsed = false, boundary = false;
  Eigen::Index sinkColumn = 0;

  // ReadOptions::ordinateSink: a real time-response record goes into the
  // next column of the hit being read, or into the next buffer's first
  // column when its load case starts a new hit.
  double* sink(const uff::Function58& f, std::uint64_t points) {
    sinkUsed = boundary = false;
    if (f.functionType != uff::FunctionType::TimeResponse || uff::isComplex(f.ordinateType)) return nullptr;
    const Eigen::Index n = static_cast<Eigen::Index>(points);
    if (onFirstLength) std::exchange(onFirstLength, nullptr)(n);
    int b = filling;
    if (count[b] > 0 && f.loadCase != hits[b].loadCase) {
      b = (filling + 1) % kBuffers;
      count[b] = 0;
      boundary = true;
    }
    Matrix& s = hits[b].record.samples;
    const Eigen::Index c = count[b];
    if (c == 0) {
      hits[b].loadCase = f.loadCase;
      if (s.rows() != n) s.resize(n, std::max<Eigen::Index>(s.cols(), 1));
    } else if (s.rows() != n) {
      return nullptr;  // length differs from the hit's first channel: next() reports it
    }
    if (c >= s.cols()) s.conservativeResize(n, std::max<Eigen::Index>(2 * s.cols(), c + 1));
    count[b] = c + 1;
    sinkUsed = true;
    sinkColumn = c;
    return s.col(c).data();
  }

  // Shrinks the finished hit's matrix to its channels and applies the
  // reference choice.
  Result<void> finish(UffHit& hit, Eigen::Index channels) {
    sg::TimeRecord& r = hit.record;
    if (r.samples.cols() != channels) r.samples.conservativeResize(r.samples.rows(), channels);
    finished.insert(hit.loadCase);
    if (references.empty()) return {};
    const std::string where = path + ", load case " + std::to_string(hit.loadCase);
    // The named DOFs are the references: among channels at such a DOF (a
    // driving point has force and response there) prefer the one typed as
    // force. Other force channels are not references.
    std::vector<std::size_t> picks;
    for (const Dof& reference : references) {
      std::optional<std::size_t> pick;
      for (std::size_t c = 0; c < r.channels.size(); ++c) {
        if (r.channels[c].dof != reference) continue;
        if (!pick || (r.channels[c].transducer.kind == sg::TransducerKind::Force &&
                      r.channels[*pick].transducer.kind != sg::TransducerKind::Force)) {
          pick = c;
        }
      }
      if (!pick) {
        return makeError(ErrorCode::NotFound, "no channel at the reference DOF " + formatDof(reference), where);
      }
      picks.push_back(*pick);
    }
    for (std::size_t c = 0; c < r.channels.size(); ++c) {
      auto& kind = r.channels[c].transducer.kind;
      if (std::find(picks.begin(), picks.end(), c) != picks.end()) {
        kind = sg::TransducerKind::Force;
      } else if (kind == sg::TransducerKind::Force) {
        kind = sg::TransducerKind::Other;  // another force channel is not a reference
      }
    }
    return {};
  }

  // Checks one record against its hit and records its channel.
  Result<void> addChannel(UffHit& hit, Eigen::Index c, const uff::Function58& f, std::int64_t line) {
    sg::TimeRecord& r = hit.record;
    const std::string where = path + ", load case " + std::to_string(f.loadCase);
    const std::string cw = where + ", channel " + std::to_string(c);
    if (c == 0) {
      if (finished.count(f.loadCase)) {
        return makeError(ErrorCode::Unsupported,
                         "load case " + std::to_string(f.loadCase) + " comes again at line " + std::to_string(line) +
                             " after other load cases: the records of one hit must be consecutive in the file",
                         where);
      }
      if (!f.evenSpacing || !(f.abscissaIncrement > 0.0)) {
        return makeError(ErrorCode::Unsupported, "time records must be evenly sampled", where);
      }
      r.channels.clear();
      r.sampleRateHz = 1.0 / f.abscissaIncrement;
      // record 7 abscissa minimum < 0: the samples before t = 0 are the pre-trigger
      r.preTriggerSamples =
          f.abscissaMin < 0.0 ? static_cast<Eigen::Index>(std::lround(-f.abscissaMin * r.sampleRateHz)) : 0;
      first = f.abscissaMin;
      firstIncrement = f.abscissaIncrement;
    } else if (!f.evenSpacing || f.abscissaIncrement != firstIncrement || f.abscissaMin != first) {
      return makeError(ErrorCode::InvalidArgument,
                       "channel's length or time axis differs from the first channel (mismatched lengths)", cw);
    }
    auto dof = f.response.dof();
    if (!dof) return makeError(dof.error().code, dof.error().message, cw);
    sg::Channel ch;
    ch.dof = *dof;
    ch.name = formatDof(*dof);
    ch.transducer.kind = kindFromUff(f.ordinateNumerator.specificDataType);
    ch.transducer.unit = f.ordinateNumerator.unitsLabel;
    r.channels.push_back(std::move(ch));
    return {};
  }
  double first = 0.0, firstIncrement = 0.0;

  Result<const UffHit*> next() {
    if (ended) return static_cast<const UffHit*>(nullptr);
    for (;;) {
      auto ds = reader->next();
      if (!ds) {
        ended = true;
        return ds.error();
      }
      if (!*ds) {  // end of file
        ended = true;
        if (count[filling] > 0) {
          if (auto ok = finish(hits[filling], count[filling]); !ok) return ok.error();
          return &hits[filling];
        }
        if (!any) {
          return makeError(ErrorCode::NotFound, "no time-response records (dataset 58, function type 1)", path);
        }
        return static_cast<const UffHit*>(nullptr);
      }
      const uff::Function58* f = (*ds)->get<uff::Function58>();
      if (!f || f->functionType != uff::FunctionType::TimeResponse) continue;
      any = true;
      const std::string where = path + ", load case " + std::to_string(f->loadCase);
      if (uff::isComplex(f->ordinateType)) {
        ended = true;
        return makeError(ErrorCode::Unsupported, "time record has complex ordinates",
                         where + ", channel " + std::to_string(count[filling]));
      }
      if (!sinkUsed) {
        ended = true;
        return makeError(ErrorCode::InvalidArgument,
                         "channel's length or time axis differs from the first channel (mismatched lengths)",
                         where + ", channel " + std::to_string(count[filling]));
      }
      const UffHit* ready = nullptr;
      if (boundary) {
        if (auto ok = finish(hits[filling], count[filling]); !ok) {
          ended = true;
          return ok.error();
        }
        ready = &hits[filling];
        filling = (filling + 1) % kBuffers;
      }
      if (auto ok = addChannel(hits[filling], sinkColumn, *f, (*ds)->line); !ok) {
        ended = true;
        return ok.error();
      }
      if (ready) return ready;
    }
  }
};

Result<UffHitReader> UffHitReader::open(const std::string& path, std::vector<Dof> references) {
  auto impl = std::make_unique<Impl>();
  impl->path = path;
  impl->references = std::move(references);
  Impl* self = impl.get();
  uff::ReadOptions options;
  options.ordinateSink = [self](const uff::Function58& f, std::uint64_t points) { return self->sink(f, points); };
  auto reader = uff::DatasetReader::open(path, std::move(options));
  if (!reader) return reader.error();
  impl->reader.emplace(std::move(reader).value());
  return UffHitReader(std::move(impl));
}

UffHitReader::UffHitReader(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
UffHitReader::UffHitReader(UffHitReader&&) noexcept = default;
UffHitReader& UffHitReader::operator=(UffHitReader&&) noexcept = default;
UffHitReader::~UffHitReader() = default;

void UffHitReader::onFirstLength(std::function<void(Eigen::Index)> callback) {
  impl_->onFirstLength = std::move(callback);
}

Result<const UffHit*> UffHitReader::next() {
  return impl_->next();
}

}  // namespace mozzi::core::io
