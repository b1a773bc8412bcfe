#include "core/protocol/unit_conventions.h"

#include <algorithm>
#include <array>

namespace ydscope {

namespace {

// Samples per second (thousands) by ranging code. G1 and the manuals: the code's own name. The
// vendor SDK's model table: G6 18/16/8 k and TG 20/18/10 k, highest code first.
constexpr std::array<std::uint16_t, 7> kG1SamplesKhz{4, 5, 8, 9, 10, 16, 18};
constexpr std::array<std::uint16_t, 3> kManualSamplesKhz{4, 8, 9};
constexpr std::array<std::uint16_t, 3> kG6FieldSamplesKhz{8, 16, 18};
constexpr std::array<std::uint16_t, 3> kTgFieldSamplesKhz{10, 18, 20};
constexpr std::array<std::uint16_t, 1> kX4SamplesKhz{5};
constexpr std::array<std::uint16_t, 1> kX2SamplesKhz{3};

enum class Family : std::uint8_t { G1, G6, TG, X4, X2 };

Family family_of(Model model) {
  switch (model) {
    case Model::G1: return Family::G1;
    case Model::G6: return Family::G6;
    case Model::TG15:
    case Model::TG30:
    case Model::TG50: return Family::TG;
    case Model::X4: return Family::X4;
    case Model::X2: return Family::X2;
  }
  return Family::G1;
}

struct Row {
  Family family;
  UnitConventions conventions;
};

constexpr ZeroPacketScanRate kNoCtRate{};
constexpr ZeroPacketScanRate kCtRate{true, 0.0};
constexpr ZeroPacketScanRate kCtRateFrom3Hz{true, 3.0};

// The one table. Reading, id, label, mm per count, correction, samples, CT scan rate, byte.
const std::array<Row, 8> kRows{{
    {Family::G1,
     {Reading::Field, "g1", "G1 manual = field: S>>2 mm, flags S&3, LastCRC", 1.0, true, kG1SamplesKhz, kNoCtRate,
      ByteBeforeZero::LapCrc8}},
    {Family::G6,
     {Reading::Field, "g6-field", "field (vendor SDK): S/2 mm, 8/16/18 k samples/s", 0.5, true, kG6FieldSamplesKhz,
      kCtRate, ByteBeforeZero::None}},
    {Family::G6,
     {Reading::Manual, "g6-manual", "manual: S/4 mm, 4/8/9 k samples/s", 0.25, true, kManualSamplesKhz, kNoCtRate,
      ByteBeforeZero::None}},
    {Family::TG,
     {Reading::Field, "tg-field", "field (vendor SDK, firmware > 1.2): S mm, no correction, 10/18/20 k samples/s", 1.0,
      false, kTgFieldSamplesKhz, kCtRateFrom3Hz, ByteBeforeZero::Unexplained}},
    {Family::TG,
     {Reading::Field, "tg-field-fw1.2",
      "field (vendor SDK, firmware <= 1.2): S/2 mm, no correction, 10/18/20 k samples/s", 0.5, false,
      kTgFieldSamplesKhz, kCtRate, ByteBeforeZero::Unexplained}},
    {Family::TG,
     {Reading::Manual, "tg-manual", "manual: S/2 mm, 4/8/9 k samples/s", 0.5, true, kManualSamplesKhz, kNoCtRate,
      ByteBeforeZero::None}},
    // X4 and X2 (decode only): the SDK reads them as triangulation units, S/4 mm corrected at S/4.
    {Family::X4,
     {Reading::Field, "x4", "X4 (vendor SDK): S/4 mm, 5 k samples/s", 0.25, true, kX4SamplesKhz, kNoCtRate,
      ByteBeforeZero::None}},
    {Family::X2,
     {Reading::Field, "x2", "X2 (vendor SDK): S/4 mm, 3 k samples/s", 0.25, true, kX2SamplesKhz, kNoCtRate,
      ByteBeforeZero::None}},
}};

const UnitConventions& row(std::string_view id) {
  for (const Row& r : kRows)
    if (r.conventions.id == id) return r.conventions;
  return kRows.front().conventions;  // unreachable: every id asked for is in the table
}

// The vendor SDK's isOldVersionTOFLidar: major <= 1 and minor <= 2, in its byte order.
bool old_tg_firmware(FirmwareVersion v) { return v.major <= 1 && v.minor <= 2; }

}  // namespace

std::optional<double> UnitConventions::samples_per_s(const ModelProfile& profile, std::uint16_t ranging_khz) const {
  const std::optional<std::uint8_t> code = profile.ranging_index(ranging_khz);
  if (!code || *code >= samples_khz.size()) return std::nullopt;
  return samples_khz[*code] * 1000.0;
}

const UnitConventions& conventions_for(const ModelProfile& profile, std::optional<FirmwareVersion> firmware,
                                       Reading reading) {
  switch (family_of(profile.model)) {
    case Family::G1: return row("g1");
    case Family::G6: return row(reading == Reading::Field ? "g6-field" : "g6-manual");
    case Family::TG:
      if (reading == Reading::Manual) return row("tg-manual");
      return row(firmware && old_tg_firmware(*firmware) ? "tg-field-fw1.2" : "tg-field");
    case Family::X4: return row("x4");
    case Family::X2: return row("x2");
  }
  return row("g1");
}

const UnitConventions* find_conventions(std::string_view id) {
  const auto it = std::find_if(kRows.begin(), kRows.end(), [id](const Row& r) { return r.conventions.id == id; });
  return it == kRows.end() ? nullptr : &it->conventions;
}

bool conventions_fit(const UnitConventions& conventions, const ModelProfile& profile) {
  return std::any_of(kRows.begin(), kRows.end(), [&](const Row& r) {
    return &r.conventions == &conventions && r.family == family_of(profile.model);
  });
}

std::string_view reading_name(Reading reading) { return reading == Reading::Field ? "field" : "manual"; }

std::optional<Reading> parse_reading(std::string_view text) {
  if (text == "field") return Reading::Field;
  if (text == "manual") return Reading::Manual;
  return std::nullopt;
}

}  // namespace ydscope
