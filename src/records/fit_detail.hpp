#pragma once
/// Pieces shared by the fragility fits (fragility.cpp) and the record-clustered errors of a
/// stripe fit (stripe_clusters.cpp). Private to the fragility library.
#include "rocksweep/records/fragility.hpp"

namespace rocksweep::fit_detail {

/// ln Phi(z), accurate in both tails.
double log_cdf(double z);
/// phi(z) / Phi(z) = d ln Phi / dz.
double mills(double z);
/// Fills the 95 % Wald intervals of `f` from its standard errors: on ln(median) and ln(beta),
/// so that both stay positive.
void intervals(FragilityFit& f);

}  // namespace rocksweep::fit_detail
