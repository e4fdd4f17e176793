#pragma once
/// The configured block and its anchorages carried to another size, slenderness or strength:
/// what the grid does when block size R, alpha or F_u/(m g) is an axis, for pulse spectra and
/// record suites alike (docs/suite.md, "Blocks").

#include "rocksweep/grid/anchorage_setting.hpp"
#include "rocksweep/grid/sweep.hpp"

namespace rocksweep {

/// The block reshaped to slenderness alpha and size R: same density, depth ∝ R (m ∝ R^3 at fixed
/// shape, ∝ sin(2 alpha) at fixed R), the same I0/(mR^2), and e as the same fraction of Housner's
/// value (1 for Housner's own). The block's own alpha and R give the block bit for bit.
/// Throws InputError (neutral field ids, block.*) for an angle or size a block cannot have.
Block reshaped_block(const Block& configured, double alpha_rad, double radius_m);

/// The scenario's anchorage on block `b`, the configured block reshaped: the same ratios
/// (F_u / (m g), theta_f / alpha, K_min / K_max) unless `set` gives them, so K follows the
/// size. On a block of the configured weight F_u is the scenario's own, so that a point whose
/// axes set what a scenario list would have set gives the same bits as that list. Throws
/// InputError (anchorage.* ids) for a spring that cannot be.
Anchorage anchorage_on(const Scenario& s, const Block& configured, const Block& b, const AnchorageSetting& set = {});

}  // namespace rocksweep
