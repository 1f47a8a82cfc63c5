#pragma once
/// Structure-of-arrays field registry for one particle set (ARCHITECTURE.md "One field registry").
/// Every per-particle array lives here, so spatial sorting, output and restart act on all fields at once.

#include "core/Types.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace poro {

/// What a particle set models (METHOD.md §1).
enum class SetKind { Fluid, Porous, Boundary };
const char* toString(SetKind kind);

enum class FieldType { Real, Vec3, Mat3, Int };

/// What happens to a field besides sorting: written to the .vtp files for viewing, and/or needed to
/// continue a run (written, and read back on restart).
enum FieldRole : unsigned { Scratch = 0u, Output = 1u, Restart = 3u /* restart fields are also output */ };

/// Names of the fields every set has or that several parts of the code share.
namespace field {
inline constexpr const char* id = "id";             ///< persistent particle id (Int)
inline constexpr const char* objectId = "objectId"; ///< sampled region / body id (Int)
inline constexpr const char* x = "x";               ///< position [m] (Vec3, the point coordinates)
inline constexpr const char* v = "v";               ///< velocity [m/s] (Vec3)
} // namespace field

class ParticleSet {
public:
  struct FieldInfo {
    std::string name;
    FieldType type;
    FieldRole role;
  };

  ParticleSet(std::string name, SetKind kind);
  ParticleSet(const ParticleSet&) = delete;
  ParticleSet& operator=(const ParticleSet&) = delete;
  ParticleSet(ParticleSet&&) noexcept;
  ParticleSet& operator=(ParticleSet&&) noexcept;
  ~ParticleSet();

  const std::string& name() const { return name_; }
  SetKind kind() const { return kind_; }
  std::size_t size() const { return size_; }

  /// Resizes every field; new entries are value-initialised (zero).
  void resize(std::size_t n);

  /// Registers a field (or returns the existing one of the same type; a different type is a logic error).
  /// References stay valid for the lifetime of the set, across resize and permute.
  std::vector<Real>& addReal(const std::string& name, FieldRole role = Scratch);
  std::vector<Vec3>& addVec3(const std::string& name, FieldRole role = Scratch);
  std::vector<Mat3>& addMat3(const std::string& name, FieldRole role = Scratch);
  std::vector<std::int64_t>& addInt(const std::string& name, FieldRole role = Scratch);

  /// Lets scratch field `name` use the storage of the scratch field `storage` (registered, of the type `name` will
  /// be registered with): for two arrays that parts of a step use at different times, so that a step holds one.
  /// Whatever one writes, the other reads. `name` is not a field of its own: fields(), fieldNames() and everything
  /// that acts on all fields see `storage` only. Call before `name` is registered; registering it as anything but
  /// scratch is then a logic error.
  void share(const std::string& name, const std::string& storage);
  /// Whether share(name, storage) would be allowed: `name` unregistered, `storage` a registered scratch field.
  bool canShare(const std::string& name, const std::string& storage) const;

  /// Unregisters field `name` if the set has it (a field read from a file that the set's model does not use).
  /// x, v, id and the storage of a shared name cannot be dropped (logic error); references to the field dangle.
  void drop(const std::string& name);

  bool has(const std::string& name) const;
  const FieldInfo* info(const std::string& name) const;
  std::vector<FieldInfo> fields() const;

  std::vector<Real>& real(const std::string& name);
  const std::vector<Real>& real(const std::string& name) const;
  std::vector<Vec3>& vec3(const std::string& name);
  const std::vector<Vec3>& vec3(const std::string& name) const;
  std::vector<Mat3>& mat3(const std::string& name);
  const std::vector<Mat3>& mat3(const std::string& name) const;
  std::vector<std::int64_t>& integer(const std::string& name);
  const std::vector<std::int64_t>& integer(const std::string& name) const;

  /// Reorders every field: new slot i receives old slot order[i]. `order` must be a permutation.
  void permute(const std::vector<Index>& order);
  /// Deletes the particles at `indices` (ascending, distinct) from every field; the others keep their order.
  void remove(const std::vector<std::size_t>& indices);
  /// A new set of the same name, kind, constants and fields (roles included) holding the particles at `slots`, in
  /// that order (a subdomain's share of a set, parallel/Decomposition.hpp).
  ParticleSet select(const std::vector<Index>& slots) const;
  /// Appends every particle of `other`, which must have the same fields (names and types; order may differ).
  void append(const ParticleSet& other);

  /// The fields named `names` (all fields when empty) of the particles at `slots`, appended to `out` as raw bytes
  /// in the order of `names` (ghost particles sent to another rank, parallel/HaloExchange.hpp).
  void pack(const std::vector<Index>& slots, const std::vector<std::string>& names, std::vector<char>& out) const;
  /// Writes `count` particles packed by pack() with the same `names` into slots first .. first + count - 1, which
  /// must exist; returns the bytes read.
  std::size_t unpack(const char* in, std::size_t count, std::size_t first, const std::vector<std::string>& names);
  /// Names of every field, in registry order (the `names` of pack() for a whole particle).
  std::vector<std::string> fieldNames() const;

  /// Shorthands for the position and velocity fields every set has.
  std::vector<Vec3>& x() { return *x_; }
  const std::vector<Vec3>& x() const { return *x_; }
  std::vector<Vec3>& v() { return *v_; }
  const std::vector<Vec3>& v() const { return *v_; }

  /// Per-set physical constants (METHOD.md §3): sampling volume V = (2r)^3, mass per particle and
  /// the density limit rho^max of the pressure constraint.
  double particleVolume = 0.0;
  double mass = 0.0;
  double restDensity = 0.0;
  /// The file the set was read from (io fills it), for messages about its particles; empty when the set was
  /// made in memory.
  std::string source;

private:
  struct FieldBase;
  template <class T> struct Field;
  FieldBase* find(const std::string& name) const;
  template <class T> std::vector<T>& add(const std::string& name, FieldType type, FieldRole role);
  template <class T> std::vector<T>& get(const std::string& name, FieldType type) const;

  std::string name_;
  SetKind kind_;
  std::size_t size_ = 0;
  std::vector<std::unique_ptr<FieldBase>> fields_;
  std::vector<std::pair<std::string, std::string>> shared_; ///< (name, storage) of share()
  std::vector<Vec3>* x_ = nullptr;
  std::vector<Vec3>* v_ = nullptr;
};

} // namespace poro
