#include "sph/ParticleSet.hpp"

#include <algorithm>
#include <cstring>
#include <type_traits>
#include <stdexcept>

namespace poro {

const char* toString(SetKind kind) {
  switch (kind) {
  case SetKind::Fluid: return "fluid";
  case SetKind::Porous: return "porous";
  case SetKind::Boundary: return "boundary";
  }
  return "?";
}

struct ParticleSet::FieldBase {
  FieldInfo info;
  virtual ~FieldBase() = default;
  virtual void resize(std::size_t n) = 0;
  virtual void permute(const std::vector<Index>& order) = 0;
  virtual std::unique_ptr<FieldBase> gathered(const std::vector<Index>& slots) const = 0;
  virtual void append(const FieldBase& other) = 0;
  virtual void pack(const std::vector<Index>& slots, std::vector<char>& out) const = 0;
  virtual std::size_t unpack(const char* in, std::size_t count, std::size_t first) = 0;
};

namespace {

/// The bytes of one field value: a scalar, or an Eigen matrix's coefficients (plain doubles, packed).
template <class T> void* bytesOf(T& value) {
  if constexpr (std::is_arithmetic_v<T>) {
    return &value;
  } else {
    static_assert(sizeof(T) == sizeof(typename T::Scalar) * T::SizeAtCompileTime, "a padded matrix type");
    return value.data();
  }
}
template <class T> const void* bytesOf(const T& value) { return bytesOf(const_cast<T&>(value)); }

} // namespace

template <class T>
struct ParticleSet::Field final : FieldBase {
  std::vector<T> data;
  void resize(std::size_t n) override { data.resize(n, T::Zero()); }
  void permute(const std::vector<Index>& order) override {
    std::vector<T> sorted(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) sorted[i] = data[static_cast<std::size_t>(order[i])];
    data.swap(sorted);
  }
  std::unique_ptr<FieldBase> gathered(const std::vector<Index>& slots) const override {
    auto copy = std::make_unique<Field<T>>();
    copy->info = info;
    copy->data.reserve(slots.size());
    for (Index i : slots) copy->data.push_back(data[static_cast<std::size_t>(i)]);
    return copy;
  }
  void append(const FieldBase& other) override {
    const auto& from = static_cast<const Field<T>&>(other).data;
    data.insert(data.end(), from.begin(), from.end());
  }
  void pack(const std::vector<Index>& slots, std::vector<char>& out) const override {
    const std::size_t at = out.size();
    out.resize(at + slots.size() * sizeof(T));
    for (std::size_t k = 0; k < slots.size(); ++k)
      std::memcpy(out.data() + at + k * sizeof(T), bytesOf(data[static_cast<std::size_t>(slots[k])]), sizeof(T));
  }
  std::size_t unpack(const char* in, std::size_t count, std::size_t first) override {
    for (std::size_t k = 0; k < count; ++k) std::memcpy(bytesOf(data[first + k]), in + k * sizeof(T), sizeof(T));
    return count * sizeof(T);
  }
};

// Scalars have no T::Zero(); specialise the value-initialising resize.
template <>
void ParticleSet::Field<Real>::resize(std::size_t n) { data.resize(n, 0.0); }
template <>
void ParticleSet::Field<std::int64_t>::resize(std::size_t n) { data.resize(n, 0); }

ParticleSet::ParticleSet(std::string name, SetKind kind) : name_(std::move(name)), kind_(kind) {
  addInt(field::id, Restart);
  addInt(field::objectId, Restart);
  x_ = &addVec3(field::x, Restart);
  v_ = &addVec3(field::v, Restart);
}

ParticleSet::ParticleSet(ParticleSet&&) noexcept = default;
ParticleSet& ParticleSet::operator=(ParticleSet&&) noexcept = default;
ParticleSet::~ParticleSet() = default;

void ParticleSet::resize(std::size_t n) {
  for (auto& f : fields_) f->resize(n);
  size_ = n;
}

ParticleSet::FieldBase* ParticleSet::find(const std::string& name) const {
  for (const auto& f : fields_)
    if (f->info.name == name) return f.get();
  for (const auto& [sharing, storage] : shared_)
    if (sharing == name) return find(storage);
  return nullptr;
}

bool ParticleSet::canShare(const std::string& name, const std::string& storage) const {
  const FieldInfo* target = info(storage);
  return target && target->role == Scratch && !has(name);
}

void ParticleSet::share(const std::string& name, const std::string& storage) {
  if (!canShare(name, storage))
    throw std::logic_error("particle set '" + name_ + "': field '" + name + "' cannot share the storage of '" +
                           storage + "' (it must be an unregistered name, and '" + storage +
                           "' a registered scratch field)");
  shared_.emplace_back(name, storage);
}

template <class T>
std::vector<T>& ParticleSet::add(const std::string& name, FieldType type, FieldRole role) {
  if (FieldBase* existing = find(name)) {
    if (existing->info.type != type)
      throw std::logic_error("particle set '" + name_ + "': field '" + name + "' registered with another type");
    if (role != Scratch && existing->info.name != name)
      throw std::logic_error("particle set '" + name_ + "': field '" + name + "' shares the storage of '" +
                             existing->info.name + "' and can only be scratch");
    if (role > existing->info.role) existing->info.role = role;
    return static_cast<Field<T>*>(existing)->data;
  }
  auto created = std::make_unique<Field<T>>();
  created->info = {name, type, role};
  created->resize(size_);
  auto& data = created->data;
  fields_.push_back(std::move(created));
  return data;
}

template <class T>
std::vector<T>& ParticleSet::get(const std::string& name, FieldType type) const {
  FieldBase* f = find(name);
  if (!f || f->info.type != type)
    throw std::logic_error("particle set '" + name_ + "' has no field '" + name + "' of the requested type");
  return static_cast<Field<T>*>(f)->data;
}

std::vector<Real>& ParticleSet::addReal(const std::string& n, FieldRole r) { return add<Real>(n, FieldType::Real, r); }
std::vector<Vec3>& ParticleSet::addVec3(const std::string& n, FieldRole r) { return add<Vec3>(n, FieldType::Vec3, r); }
std::vector<Mat3>& ParticleSet::addMat3(const std::string& n, FieldRole r) { return add<Mat3>(n, FieldType::Mat3, r); }
std::vector<std::int64_t>& ParticleSet::addInt(const std::string& n, FieldRole r) {
  return add<std::int64_t>(n, FieldType::Int, r);
}

void ParticleSet::drop(const std::string& name) {
  const auto it = std::find_if(fields_.begin(), fields_.end(), [&](const auto& f) { return f->info.name == name; });
  if (it == fields_.end()) return;
  const bool shared = std::any_of(shared_.begin(), shared_.end(), [&](const auto& s) { return s.second == name; });
  if (name == field::x || name == field::v || name == field::id || shared)
    throw std::logic_error("particle set '" + name_ + "': field '" + name + "' cannot be dropped");
  fields_.erase(it);
}

bool ParticleSet::has(const std::string& name) const { return find(name) != nullptr; }

const ParticleSet::FieldInfo* ParticleSet::info(const std::string& name) const {
  const FieldBase* f = find(name);
  return f ? &f->info : nullptr;
}

std::vector<ParticleSet::FieldInfo> ParticleSet::fields() const {
  std::vector<FieldInfo> result;
  result.reserve(fields_.size());
  for (const auto& f : fields_) result.push_back(f->info);
  return result;
}

std::vector<Real>& ParticleSet::real(const std::string& n) { return get<Real>(n, FieldType::Real); }
const std::vector<Real>& ParticleSet::real(const std::string& n) const { return get<Real>(n, FieldType::Real); }
std::vector<Vec3>& ParticleSet::vec3(const std::string& n) { return get<Vec3>(n, FieldType::Vec3); }
const std::vector<Vec3>& ParticleSet::vec3(const std::string& n) const { return get<Vec3>(n, FieldType::Vec3); }
std::vector<Mat3>& ParticleSet::mat3(const std::string& n) { return get<Mat3>(n, FieldType::Mat3); }
const std::vector<Mat3>& ParticleSet::mat3(const std::string& n) const { return get<Mat3>(n, FieldType::Mat3); }
std::vector<std::int64_t>& ParticleSet::integer(const std::string& n) { return get<std::int64_t>(n, FieldType::Int); }
const std::vector<std::int64_t>& ParticleSet::integer(const std::string& n) const {
  return get<std::int64_t>(n, FieldType::Int);
}

void ParticleSet::permute(const std::vector<Index>& order) {
  if (order.size() != size_) throw std::logic_error("ParticleSet::permute: order has the wrong length");
  for (auto& f : fields_) f->permute(order);
}

void ParticleSet::remove(const std::vector<std::size_t>& indices) {
  std::vector<Index> kept;
  kept.reserve(size_);
  std::size_t next = 0; // position in `indices`
  for (std::size_t i = 0; i < size_; ++i) {
    if (next < indices.size() && indices[next] == i) {
      ++next;
      continue;
    }
    kept.push_back(static_cast<Index>(i));
  }
  if (next != indices.size()) throw std::logic_error("ParticleSet::remove: indices not ascending or out of range");
  for (auto& f : fields_) f->permute(kept); // a gather into kept.size() slots
  size_ = kept.size();
}

ParticleSet ParticleSet::select(const std::vector<Index>& slots) const {
  for (Index i : slots)
    if (i < 0 || static_cast<std::size_t>(i) >= size_) throw std::logic_error("ParticleSet::select: slot out of range");
  ParticleSet result(name_, kind_);
  result.fields_.clear();
  for (const auto& f : fields_) result.fields_.push_back(f->gathered(slots));
  result.shared_ = shared_;
  result.size_ = slots.size();
  result.x_ = &result.get<Vec3>(field::x, FieldType::Vec3);
  result.v_ = &result.get<Vec3>(field::v, FieldType::Vec3);
  result.particleVolume = particleVolume;
  result.mass = mass;
  result.restDensity = restDensity;
  result.source = source;
  return result;
}

void ParticleSet::append(const ParticleSet& other) {
  if (other.fields_.size() != fields_.size())
    throw std::logic_error("ParticleSet::append: sets '" + name_ + "' and '" + other.name_ + "' have other fields");
  for (auto& f : fields_) {
    const FieldBase* from = other.find(f->info.name);
    if (!from || from->info.type != f->info.type)
      throw std::logic_error("ParticleSet::append: set '" + other.name_ + "' has no field '" + f->info.name +
                             "' of the same type");
  }
  for (auto& f : fields_) f->append(*other.find(f->info.name));
  size_ += other.size_;
}

void ParticleSet::pack(const std::vector<Index>& slots, const std::vector<std::string>& names,
                       std::vector<char>& out) const {
  for (const std::string& name : names.empty() ? fieldNames() : names) {
    const FieldBase* f = find(name);
    if (!f) throw std::logic_error("ParticleSet::pack: set '" + name_ + "' has no field '" + name + "'");
    f->pack(slots, out);
  }
}

std::size_t ParticleSet::unpack(const char* in, std::size_t count, std::size_t first,
                                const std::vector<std::string>& names) {
  if (first + count > size_) throw std::logic_error("ParticleSet::unpack: slots beyond the set's size");
  std::size_t read = 0;
  for (const std::string& name : names.empty() ? fieldNames() : names) {
    FieldBase* f = find(name);
    if (!f) throw std::logic_error("ParticleSet::unpack: set '" + name_ + "' has no field '" + name + "'");
    read += f->unpack(in + read, count, first);
  }
  return read;
}

std::vector<std::string> ParticleSet::fieldNames() const {
  std::vector<std::string> names;
  for (const auto& f : fields_) names.push_back(f->info.name);
  return names;
}

} // namespace poro
