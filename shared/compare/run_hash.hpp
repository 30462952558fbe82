#pragma once
// The key of the run cache: runs/<hash>/ holds a completed run, reused unless --force.
#include <nlohmann/json.hpp>
#include <string>

namespace altfem {

/// 16 hex digits of FNV-1a (64 bit) over the method name and the resolved scene
/// (every default filled, paths absolute) without its `name` and `compare` keys, which
/// do not change what a run computes. nlohmann::json orders object keys, so the dump
/// is canonical: equal options give equal hashes whatever the key order of the file.
std::string run_hash(const std::string& method, const nlohmann::json& resolved_scene);

}  // namespace altfem
