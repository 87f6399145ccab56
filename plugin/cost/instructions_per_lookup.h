#pragma once
// Instructions per lookup, counted by callgrind: deterministic, unlike time, so a CTest can
// assert it and `probeproxy bench` reports it as `instructions_per_lookup`.
//
// Runs the driver (lookup_cost_driver.cpp) under
//   valgrind --tool=callgrind --instr-atstart=no --collect-atstart=no
// for N and for 2N lookups of the same workload (lookup_workload.h; the first N rays are the
// same) and returns (I(2N) - I(N)) / N, so whatever a run does once (the first call's lazy
// symbol binding, a batched call's set-up and tail) cancels.

#include "plugin/cost/lookup_workload.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace probeproxy {

enum class LookupPath { Scalar, Batched };  // lookupScalar per ray, or one lookupBatch call

// probeproxy_lookup_cost_driver beside the running executable if there is one, else the one
// the build tree made.
std::filesystem::path lookupCostDriverPath();

// nullopt when valgrind is not on PATH (the figure was not measured: report null). Throws
// std::invalid_argument for an unknown workload name or lookups == 0, std::runtime_error when
// the driver is missing, or the driver or valgrind fails (naming the command).
std::optional<double> instructionsPerLookup(
    const std::string& workload, LookupPath path, std::size_t lookups = 4096,
    const std::filesystem::path& driver = lookupCostDriverPath());

// The same for many workloads in ONE valgrind run (the driver's --dumps mode: each region is
// counted alone, so the figures equal the one-workload calls'); valgrind's start-up, most of a
// run's time, is paid once. One entry per workload, in order; all nullopt without valgrind.
std::vector<std::optional<double>> instructionsPerLookup(
    const std::vector<std::string>& workloads, LookupPath path, std::size_t lookups = 4096,
    const std::filesystem::path& driver = lookupCostDriverPath());

}  // namespace probeproxy
