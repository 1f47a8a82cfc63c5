#include "physics/StateSnapshot.hpp"

#include "core/Parallel.hpp"

#include <algorithm>

namespace poro {

namespace {

/// Copies `from` into the alternative T of `to`, reusing its capacity when it already holds a T. On all threads:
/// the copy is taken before every step, and the other threads would wait for it.
template <class T, class Variant> void copyInto(Variant& to, const std::vector<T>& from) {
  auto* held = std::get_if<std::vector<T>>(&to);
  if (!held) held = &to.template emplace<std::vector<T>>();
  held->resize(from.size());
  T* const out = held->data();
  const T* const in = from.data();
  parallel::forEach(from.size(), [&](std::size_t i) { out[i] = in[i]; });
}

} // namespace

void StateSnapshot::take(const ParticleSystem& particles, const std::vector<std::size_t>& sets, const RunState& state,
                         const std::vector<std::string>& keptInPlace, const std::vector<std::string>& formedAgain) {
  const auto named = [](const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  state_ = state;
  sets_.resize(sets.size());
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const ParticleSet& set = particles[sets[k]];
    Set& copy = sets_[k];
    copy.index = sets[k];
    copy.size = set.size();
    std::size_t n = 0;
    for (const auto& info : set.fields()) {
      if (!(info.role & Output) || named(keptInPlace, info.name) || named(formedAgain, info.name)) continue;
      if (n == copy.fields.size()) copy.fields.emplace_back();
      Field& field = copy.fields[n++];
      field.name = info.name;
      switch (info.type) {
      case FieldType::Real: copyInto(field.data, set.real(info.name)); break;
      case FieldType::Vec3: copyInto(field.data, set.vec3(info.name)); break;
      case FieldType::Mat3: copyInto(field.data, set.mat3(info.name)); break;
      case FieldType::Int: copyInto(field.data, set.integer(info.name)); break;
      }
    }
    copy.fields.resize(n);
  }
}

void StateSnapshot::restore(ParticleSystem& particles, RunState& state) const {
  state = state_;
  for (const Set& copy : sets_) {
    ParticleSet& set = particles[copy.index];
    set.resize(copy.size);
    for (const Field& field : copy.fields) {
      std::visit(
          [&](const auto& data) {
            using T = typename std::decay_t<decltype(data)>::value_type;
            if constexpr (std::is_same_v<T, Real>) set.real(field.name) = data;
            else if constexpr (std::is_same_v<T, Vec3>) set.vec3(field.name) = data;
            else if constexpr (std::is_same_v<T, Mat3>) set.mat3(field.name) = data;
            else set.integer(field.name) = data;
          },
          field.data);
    }
  }
}

std::optional<Vec3> StateSnapshot::positionOf(std::size_t set, std::size_t index, std::int64_t id) const {
  for (const Set& copy : sets_) {
    if (copy.index != set) continue;
    const std::vector<std::int64_t>* ids = nullptr;
    const std::vector<Vec3>* x = nullptr;
    for (const Field& f : copy.fields) {
      if (f.name == field::id) ids = std::get_if<std::vector<std::int64_t>>(&f.data);
      if (f.name == field::x) x = std::get_if<std::vector<Vec3>>(&f.data);
    }
    if (!x) return std::nullopt;
    if (!ids) return index < x->size() ? std::optional<Vec3>((*x)[index]) : std::nullopt; // the order is kept
    for (std::size_t i = 0; i < ids->size(); ++i)
      if ((*ids)[i] == id) return (*x)[i];
  }
  return std::nullopt;
}

} // namespace poro
