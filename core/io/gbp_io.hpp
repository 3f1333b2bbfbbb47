// The .gbp format (docs/gbp-format.md): one convex GB patch as whitespace-separated
// numbers "n d", the central point, then the boundary and inner layers in GBPatch's point order.
#pragma once

#include <filesystem>
#include <string>

#include "core/patch/gb/gb_patch.hpp"

namespace pl {

// Every error is a DataError(source, "token N", message), N counted from 1.
GBPatch parse_gbp(const std::string& text, const std::string& source);
GBPatch read_gbp(const std::filesystem::path& path);

// 17 significant digits: reading the text back gives the same doubles.
std::string gbp_to_text(const GBPatch& patch);
void write_gbp(const std::filesystem::path& path, const GBPatch& patch);  // atomic

}  // namespace pl
