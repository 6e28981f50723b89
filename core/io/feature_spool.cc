#include "core/io/feature_spool.h"

#include <algorithm>
#include <cstring>
#include <string_view>

#include "core/io/io_error.h"

namespace procex {
namespace {

// A record's bytes: counts and lengths as 64-bit numbers, coordinates and
// angles as doubles, in this machine's byte order (the file is read back
// by the process that wrote it, never by another).
class RecordWriter {
 public:
  void number(std::uint64_t v) { raw(&v, sizeof v); }
  void text(std::string_view s) { number(s.size()), out.append(s); }
  void doubles(const double* v, std::size_t n) { number(n), raw(v, n * sizeof(double)); }
  void points(const std::vector<glm::dvec2>& v) { doubles(reinterpret_cast<const double*>(v.data()), v.size() * 2); }
  std::string out;

 private:
  void raw(const void* p, std::size_t n) {
    if (n > 0) out.append(static_cast<const char*>(p), n);
  }
};

class RecordReader {
 public:
  explicit RecordReader(std::string_view in) : in_(in) {}
  std::uint64_t number() {
    std::uint64_t v = 0;
    raw(&v, sizeof v);
    return v;
  }
  std::string text() {
    const std::size_t n = length(1);
    std::string s(in_.substr(0, n));
    in_.remove_prefix(n);
    return s;
  }
  // As many doubles as the record says, per_item to an element of out.
  template <typename T>
  void doubles(std::vector<T>& out, std::size_t per_item) {
    const std::size_t n = length(sizeof(double));
    if (n % per_item != 0) broken();
    out.resize(n / per_item);
    raw(out.data(), n * sizeof(double));
  }
  // A count of items of `size` bytes the rest of the record can hold.
  std::size_t length(std::size_t size) {
    const std::uint64_t n = number();
    if (n > in_.size() / size) broken();
    return static_cast<std::size_t>(n);
  }

 private:
  void raw(void* p, std::size_t n) {
    if (n > in_.size()) broken();
    if (n == 0) return;
    std::memcpy(p, in_.data(), n);
    in_.remove_prefix(n);
  }
  [[noreturn]] static void broken() {
    throw IoError("a footprint set aside in a temporary file came back cut short or changed", "");
  }
  std::string_view in_;
};

static_assert(sizeof(glm::dvec2) == 2 * sizeof(double));

std::string record_of(const GeoJsonFeature& f) {
  RecordWriter w;
  w.number(f.index);
  w.text(f.id);
  w.number(f.loops.size());
  for (const auto& loop : f.loops) w.points(loop);
  w.number(f.polygon_of_loop.size());
  for (const std::size_t p : f.polygon_of_loop) w.number(p);
  w.number(f.properties.size());
  for (const auto& [name, value] : f.properties) w.text(name), w.text(value);
  w.number(f.edge_angles.size());
  for (const auto& angles : f.edge_angles) w.doubles(angles.data(), angles.size());
  return std::move(w.out);
}

GeoJsonFeature feature_of(std::string_view record) {
  RecordReader r(record);
  GeoJsonFeature f;
  f.index = r.number();
  f.id = r.text();
  f.loops.resize(r.length(sizeof(std::uint64_t)));
  for (auto& loop : f.loops) r.doubles(loop, 2);
  f.polygon_of_loop.resize(r.length(sizeof(std::uint64_t)));
  for (std::size_t& p : f.polygon_of_loop) p = r.number();
  for (std::size_t n = r.length(2 * sizeof(std::uint64_t)); n > 0; --n) {
    std::string name = r.text();
    f.properties.emplace_hint(f.properties.end(), std::move(name), r.text());
  }
  f.edge_angles.resize(r.length(sizeof(std::uint64_t)));
  for (auto& angles : f.edge_angles) r.doubles(angles, 1);
  return f;
}

std::string properties_record(const std::vector<std::pair<std::string, std::string>>& properties) {
  RecordWriter w;
  w.number(properties.size());
  for (const auto& [name, value] : properties) w.text(name), w.text(value);
  return std::move(w.out);
}

std::vector<std::pair<std::string, std::string>> properties_of(std::string_view record) {
  RecordReader r(record);
  std::vector<std::pair<std::string, std::string>> out(r.length(2 * sizeof(std::uint64_t)));
  for (auto& [name, value] : out) name = r.text(), value = r.text();
  return out;
}

}  // namespace

FeatureSpool::FeatureSpool(std::string folder) : folder_(std::move(folder)), file_(std::make_unique<SpoolFile>(folder_)) {}

FeatureSpool::Range FeatureSpool::append(const std::string& record) {
  const Range r{file_->size(), record.size()};
  file_->append(record);
  return r;
}

void FeatureSpool::add(GeoJsonFeature f) {
  const std::size_t index = f.index;
  entries_.push_back({index, append(record_of(f)), {}});
}

void FeatureSpool::clear() {
  file_ = std::make_unique<SpoolFile>(folder_);
  entries_.clear();
}

// Into a new file, in order: what is dropped or changed leaves no bytes behind.
void FeatureSpool::keep_if(const std::function<bool(GeoJsonFeature&)>& keep) {
  std::unique_ptr<SpoolFile> from = std::exchange(file_, std::make_unique<SpoolFile>(folder_));
  std::vector<Entry> entries = std::exchange(entries_, {});
  for (const Entry& e : entries) {
    GeoJsonFeature f = feature_of(from->read_at(e.feature.at, e.feature.length));
    if (!keep(f)) continue;
    Entry kept{e.index, append(record_of(f)), {}};
    if (e.added.length > 0) kept.added = append(from->read_at(e.added.at, e.added.length));
    entries_.push_back(kept);
  }
}

GeoJsonFeature FeatureSpool::at(std::size_t i) const {
  const Entry& e = entries_.at(i);
  GeoJsonFeature f = feature_of(file_->read_at(e.feature.at, e.feature.length));
  if (e.added.length > 0)
    for (auto& [name, value] : properties_of(file_->read_at(e.added.at, e.added.length)))
      f.properties.try_emplace(std::move(name), std::move(value));
  return f;
}

void FeatureSpool::add_properties(std::size_t i, const std::vector<std::pair<std::string, std::string>>& properties) {
  Entry& e = entries_.at(i);
  std::vector<std::pair<std::string, std::string>> all;
  if (e.added.length > 0) all = properties_of(file_->read_at(e.added.at, e.added.length));
  for (const auto& p : properties)
    if (std::none_of(all.begin(), all.end(), [&](const auto& q) { return q.first == p.first; })) all.push_back(p);
  e.added = append(properties_record(all));
}

}  // namespace procex
