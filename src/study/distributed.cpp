#include <feran/study/distributed.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>

#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

namespace {

// The packed form: "FEV1", the count, then per evaluation its index, the three
// vectors (a count and the doubles' bytes), a byte of flags, the message (a count and
// its bytes) and the seconds. In the byte order of the machine: the processes of one
// study run the same program on the same kind of machine.
constexpr char magic[4] = {'F', 'E', 'V', '1'};

class Writer {
 public:
  template <class T>
  void put(const T& v) {
    const auto* p = reinterpret_cast<const char*>(&v);
    out.append(p, sizeof(T));
  }
  void put_reals(const std::vector<Real>& v) {
    put(static_cast<std::uint64_t>(v.size()));
    if (!v.empty()) out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(Real));
  }
  void put_text(const std::string& s) {
    put(static_cast<std::uint64_t>(s.size()));
    out.append(s);
  }
  std::string out;
};

class Reader {
 public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  template <class T>
  T get() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  std::vector<Real> get_reals() {
    const auto n = get<std::uint64_t>();
    need_items(n, sizeof(Real));
    std::vector<Real> v(static_cast<std::size_t>(n));
    if (!v.empty()) std::memcpy(v.data(), bytes_.data() + at_, v.size() * sizeof(Real));  // data() may be null
    at_ += v.size() * sizeof(Real);
    return v;
  }
  std::string get_text() {
    const auto n = get<std::uint64_t>();
    need_items(n, 1);
    std::string s = bytes_.substr(at_, static_cast<std::size_t>(n));
    at_ += s.size();
    return s;
  }
  bool at_end() const { return at_ == bytes_.size(); }

 private:
  void need(std::size_t n) const {
    if (bytes_.size() - at_ < n)
      throw Error(fmt::format("packed evaluations cut short at byte {} of {}", at_, bytes_.size()));
  }
  void need_items(std::uint64_t n, std::size_t item) const {
    if (n > (bytes_.size() - at_) / item)
      throw Error(fmt::format("packed evaluations cut short at byte {} of {}", at_, bytes_.size()));
  }
  const std::string& bytes_;
  std::size_t at_ = 0;
};

}  // namespace

std::string pack_evaluations(std::span<const Evaluation> evaluations) {
  Writer w;
  w.out.append(magic, sizeof magic);
  w.put(static_cast<std::uint64_t>(evaluations.size()));
  for (const auto& e : evaluations) {
    w.put(static_cast<std::int64_t>(e.index));
    w.put_reals(e.unit);
    w.put_reals(e.values);
    w.put_reals(e.quantities);
    w.put(static_cast<std::uint8_t>((e.evaluated ? 1 : 0) | (e.feasible ? 2 : 0) | (e.interrupted ? 4 : 0)));
    w.put_text(e.message);
    w.put(static_cast<std::uint64_t>(e.clipped.size()));
    for (const auto& c : e.clipped) w.put_text(c);
    w.put(e.seconds);
  }
  return std::move(w.out);
}

std::vector<Evaluation> unpack_evaluations(const std::string& bytes) {
  if (bytes.size() < sizeof magic || std::memcmp(bytes.data(), magic, sizeof magic) != 0)
    throw Error("not a list of packed evaluations");
  const std::string body = bytes.substr(sizeof magic);
  Reader r(body);
  const auto n = r.get<std::uint64_t>();
  std::vector<Evaluation> out;
  for (std::uint64_t k = 0; k < n; ++k) {
    Evaluation e;
    e.index = static_cast<Index>(r.get<std::int64_t>());
    e.unit = r.get_reals();
    e.values = r.get_reals();
    e.quantities = r.get_reals();
    const auto flags = r.get<std::uint8_t>();
    if (flags > 7) throw Error(fmt::format("packed evaluation {} has unknown flags {}", e.index, flags));
    e.evaluated = (flags & 1) != 0;
    e.feasible = (flags & 2) != 0;
    e.interrupted = (flags & 4) != 0;
    e.message = r.get_text();
    const auto n_clipped = r.get<std::uint64_t>();
    if (n_clipped > e.quantities.size())
      throw Error(fmt::format("packed evaluation {} has {} clipped notes for {} quantities", e.index, n_clipped,
                              e.quantities.size()));
    for (std::uint64_t i = 0; i < n_clipped; ++i) e.clipped.push_back(r.get_text());
    e.seconds = r.get<Real>();
    out.push_back(std::move(e));
  }
  if (!r.at_end()) throw Error("packed evaluations followed by stray bytes");
  return out;
}

bool all_agree(Communicator& group, bool ok, const std::string& message, std::string* first_message) {
  // Each member sends "1" or "0" and its message.
  const auto all = group.all_gather((ok ? "1" : "0") + message);
  for (std::size_t r = 0; r < all.size(); ++r) {
    if (!all[r].empty() && all[r][0] == '1') continue;
    if (first_message != nullptr) {
      const std::string text = all[r].empty() ? std::string("failed") : all[r].substr(1);
      *first_message = r == 0 ? text : fmt::format("process {}: {}", r, text);
    }
    return false;
  }
  return true;
}

std::vector<Evaluation> DistributedEvaluator::evaluate(const StudySpec& study,
                                                       const std::vector<std::pair<Index, UnitPoint>>& batch) {
  const int size = group_.size();
  const int rank = group_.rank();
  std::vector<std::pair<Index, UnitPoint>> mine;
  for (std::size_t i = static_cast<std::size_t>(rank); i < batch.size(); i += static_cast<std::size_t>(size))
    mine.push_back(batch[i]);
  const auto local = mine.empty() ? std::vector<Evaluation>{} : local_.evaluate(study, mine);
  if (local.size() != mine.size()) throw Error("a process's evaluator returned the wrong number of evaluations");
  // A leading byte says whether this member was asked to stop.
  const auto parts = group_.all_gather((stop_.requested() ? "1" : "0") + pack_evaluations(local));
  std::vector<Evaluation> out(batch.size());
  bool stop = false;
  for (int r = 0; r < size; ++r) {
    const std::string& part = parts[static_cast<std::size_t>(r)];
    if (part.empty()) throw Error(fmt::format("process {} sent no evaluations", r));
    stop = stop || part[0] == '1';
    auto theirs = unpack_evaluations(part.substr(1));
    std::size_t k = 0;
    for (std::size_t i = static_cast<std::size_t>(r); i < batch.size(); i += static_cast<std::size_t>(size), ++k) {
      if (k >= theirs.size() || theirs[k].index != batch[i].first)
        throw Error(fmt::format("process {} sent other evaluations than its share of the batch", r));
      out[i] = std::move(theirs[k]);
    }
    if (k != theirs.size()) throw Error(fmt::format("process {} sent more evaluations than its share of the batch", r));
  }
  if (stop) stopped_->store(true);
  return out;
}

}  // namespace feran
