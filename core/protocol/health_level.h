#pragma once
// How bad a health answer is, decided in one place for every program: the CLI's health line and
// exit status (scan, record), check's health criterion and the app's health badge.
#include <cstdint>
#include <string_view>

#include "core/protocol/commands.h"

namespace ydscope {

enum class HealthLevel : std::uint8_t { Ok, Warning, Error };

// G1 module bits (the A5 92 status byte, and CT health): any of bits 0..5 set is an error (the
// manual: that module is abnormal); bits 6 and 7 are reserved and ignored.
HealthLevel health_bits_level(std::uint8_t bits);
// G6/TG A5 91: status 0 with error code 0 is ok; status 1, or 0 with an error code, a warning;
// status 2, or a status the manuals do not define, an error.
HealthLevel health_status_level(std::uint8_t status, std::uint16_t error_code);
// By the command that answered (a unit may answer the other model's command: see the fallback).
HealthLevel health_level(Command command, std::uint8_t status, std::uint16_t error_code);

// "ok", "warning", "error"
std::string_view health_level_name(HealthLevel level);

}  // namespace ydscope
