#pragma once
/// The configured block and its anchorages carried to another size, slenderness or strength:
/// what the grid does when block size R, alpha or F_u/(m g) is an axis, for pulse spectra and
/// record suites alike (docs/suite.md, "Blocks").
#include <optional>

#include "rocksweep/grid/sweep.hpp"

namespace rocksweep {

/// The block reshaped to slenderness alpha and size R: same density, depth ∝ R (m ∝ R^3 at fixed
/// shape, ∝ sin(2 alpha) at fixed R), the same I0/(mR^2), and e as the same fraction of Housner's
/// value (1 for Housner's own). The block's own alpha and R give the block bit for bit.
/// Throws InputError (neutral field ids, block.*) for an angle or size a block cannot have.
Block reshaped_block(const Block& configured, double alpha_rad, double radius_m);

/// The scenario's anchorage on block `b`, the configured block reshaped: the same ratios
/// (F_u / (m g), or `strength_ratio` where given; theta_f / alpha; K_min / K_max), so K follows the size.
/// Always rebuilt from the ratios, also on the configured block (the last bit of F_u may differ
/// from the scenario's own): callers whose block is unchanged keep the scenario's anchorage.
Anchorage anchorage_on(const Scenario& s, const Block& configured, const Block& b, std::optional<double> strength_ratio = std::nullopt);

}  // namespace rocksweep
