// The model's settings by name: for each config key (config/default.yaml),
// its unit, the one range it is checked against, and the ModelSpec field it
// sets. The config parser reads the keys through it, Model's constructor and
// Model::retuned check every value against it, and the node's live tuning
// names them after it (the key with '.' as '_': contact.friction is
// dynamic_reconfigure's contact_friction). The fields carry the key's last
// part as their name (contact.friction is ContactSettings::friction); gravity
// is ModelSpec::gravity_W, the frame its vector is in.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "rigid_body_sim/core/bodies/model.h"

namespace rigid_body_sim::core {

struct SettingKey {
  enum class Kind {
    kNumber,  ///< a finite double within [min, max] (or (min, max] when min_open)
    kCount,   ///< a whole number within [min, max]
    kFlag,    ///< true or false
    kChoice,  ///< one of `choices`, parsed by the config's own code
    kVector,  ///< three finite numbers whose length is at most max
  };
  std::string_view key;   ///< "contact.friction"
  std::string_view unit;  ///< "m/s"; "" for a pure number
  Kind kind = Kind::kNumber;
  double min = 0.0;                         ///< kNumber, kCount
  double max = 0.0;                         ///< kNumber, kCount; kVector: of the length; may be +∞
  bool min_open = false;                    ///< kNumber: min itself is refused
  std::string_view choices;                 ///< kChoice: the accepted words, "a | b | c"
  double* (*number)(ModelSpec&) = nullptr;  ///< kNumber
  int* (*count)(ModelSpec&) = nullptr;      ///< kCount
  bool* (*flag)(ModelSpec&) = nullptr;      ///< kFlag
  Vec3* (*vector)(ModelSpec&) = nullptr;    ///< kVector

  /// The section a key is in ("contact"), "" for a top-level key.
  std::string_view section() const;
  /// Its name within the section ("friction").
  std::string_view name() const;
  /// Its dynamic_reconfigure name: the key with '.' as '_'.
  std::string reconfigureName() const;
  /// The range in words: "within [0, 10]", "> 0 and at most 1", "finite and >= 0".
  std::string range() const;
};

/// Every model setting a config may set, in config/default.yaml's order.
const std::vector<SettingKey>& settingKeys();

/// The entry of `key`, or nullptr.
const SettingKey* findSettingKey(std::string_view key);

/// Throws std::invalid_argument "<key> = <value>: must be <range> <unit>"
/// unless `value` is within the key's range (kNumber, kCount) or its length
/// is (kVector).
void checkSetting(const SettingKey& key, double value);
void checkSetting(const SettingKey& key, const Vec3& value);

/// Checks every number, count and vector of `spec` against its key's range.
void checkSettings(const ModelSpec& spec);

}  // namespace rigid_body_sim::core
