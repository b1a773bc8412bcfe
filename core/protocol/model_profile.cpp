#include "core/protocol/model_profile.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace ydscope {

namespace {

constexpr std::array<std::uint16_t, 7> kG1RangingKhz{4, 5, 8, 9, 10, 16, 18};
constexpr std::array<std::uint16_t, 3> kG6TgRangingKhz{4, 8, 9};

constexpr std::array kG1Commands{
    Command::Scan,
    Command::Stop,
    Command::DeviceInfo,
    Command::HealthStatusBits,
    Command::ScanHzUpTenth,
    Command::ScanHzDownTenth,
    Command::ScanHzUpOne,
    Command::ScanHzDownOne,
    Command::ScanHzGet,
    Command::RangingGet,
    Command::PowerDownProtection,
    Command::RestartG1,
};

constexpr std::array kG6Commands{
    Command::Scan,           Command::Stop,          Command::DeviceInfo,          Command::HealthStatusCode,
    Command::LowPowerOn,     Command::LowPowerOff,   Command::MotorClockwise,      Command::MotorCounterClockwise,
    Command::MotorDirection, Command::ScanHzUpTenth, Command::ScanHzDownTenth,     Command::ScanHzUpOne,
    Command::ScanHzDownOne,  Command::ScanHzGet,     Command::ConstantHzOn,        Command::ConstantHzOff,
    Command::RangingCycle,   Command::RangingGet,    Command::PowerDownProtection, Command::RestartG6TG,
};

// The TG manual lists A5 05 (module status) in its command chart and documents motor direction.
constexpr std::array kTgCommands{
    Command::Scan,
    Command::Stop,
    Command::DeviceInfo,
    Command::HealthStatusCode,
    Command::LowPowerOn,
    Command::LowPowerOff,
    Command::ModuleStatus,
    Command::MotorClockwise,
    Command::MotorCounterClockwise,
    Command::MotorDirection,
    Command::ScanHzUpTenth,
    Command::ScanHzDownTenth,
    Command::ScanHzUpOne,
    Command::ScanHzDownOne,
    Command::ScanHzGet,
    Command::ConstantHzOn,
    Command::ConstantHzOff,
    Command::RangingCycle,
    Command::RangingGet,
    Command::PowerDownProtection,
    Command::RestartG6TG,
};

// Scan-frequency limits and defaults are not in the manuals; they are the datasheets' 5-12 Hz range.
constexpr ModelProfile tg(Model model, std::string_view name, std::uint8_t code) {
  return {model,           name, code, 512000, 0,    false, false,      Command::HealthStatusCode, Command::RestartG6TG,
          kG6TgRangingKhz, 9,    true, 5.0,    12.0, 10.0,  kTgCommands};
}

// X4: the vendor SDK's model table (code 6, 128000 baud, 5 k samples/s, PWM motor 5-12 Hz) and
// its commands (scan, stop, device info, health, restart). X2: 115200 baud, 3 k samples/s, 4-8 Hz,
// no commands at all (it streams from power-on).
constexpr std::array kX4Commands{Command::Scan, Command::Stop, Command::DeviceInfo, Command::HealthStatusBits,
                                 Command::RestartG1};
constexpr std::array<std::uint16_t, 1> kX4RangingKhz{5};
constexpr std::array<std::uint16_t, 1> kX2RangingKhz{3};

constexpr std::size_t kDrivenModels = 5;
constexpr std::array<ModelProfile, 7> kProfiles{{
    {Model::G1, "G1", 19, 230400, 2, true, true, Command::HealthStatusBits, Command::RestartG1, kG1RangingKhz, 9, false,
     5.0, 12.0, 9.0, kG1Commands},
    {Model::G6, "G6", 13, 512000, 0, false, false, Command::HealthStatusCode, Command::RestartG6TG, kG6TgRangingKhz, 9,
     true, 5.0, 12.0, 8.0, kG6Commands},
    tg(Model::TG15, "TG15", 100),
    tg(Model::TG30, "TG30", 101),
    tg(Model::TG50, "TG50", 102),
    {Model::X4, "X4", 6, 128000, 0, false, false, Command::HealthStatusBits, Command::RestartG1, kX4RangingKhz, 5,
     false, 5.0, 12.0, 7.0, kX4Commands},
    {Model::X2,
     "X2",
     6,
     115200,
     0,
     false,
     false,
     Command::HealthStatusBits,
     Command::RestartG1,
     kX2RangingKhz,
     3,
     false,
     4.0,
     8.0,
     7.0,
     {}},
}};

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

}  // namespace

bool ModelProfile::supports(Command command) const {
  return std::find(commands.begin(), commands.end(), command) != commands.end();
}

std::optional<std::uint8_t> ModelProfile::ranging_index(std::uint16_t khz) const {
  const auto it = std::find(ranging_khz.begin(), ranging_khz.end(), khz);
  if (it == ranging_khz.end()) return std::nullopt;
  return static_cast<std::uint8_t>(it - ranging_khz.begin());
}

std::span<const ModelProfile> all_profiles() { return std::span(kProfiles).first(kDrivenModels); }

std::span<const ModelProfile> decode_only_profiles() { return std::span(kProfiles).subspan(kDrivenModels); }

const ModelProfile* find_decodable_profile(std::string_view name) {
  for (const auto& profile : kProfiles)
    if (equals_ignoring_case(profile.name, name)) return &profile;
  return nullptr;
}

const ModelProfile& profile_for(Model model) { return kProfiles[static_cast<std::size_t>(model)]; }

const ModelProfile* find_profile(std::string_view name) {
  for (const auto& profile : all_profiles())
    if (equals_ignoring_case(profile.name, name)) return &profile;
  return nullptr;
}

const ModelProfile* find_profile_by_code(std::uint8_t model_code) {
  for (const auto& profile : all_profiles())
    if (profile.model_code == model_code) return &profile;
  return nullptr;
}

std::string_view model_names() { return "G1, G6, TG15, TG30, TG50"; }

}  // namespace ydscope
