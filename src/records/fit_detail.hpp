#pragma once
/// Pieces shared by the fragility fits (fragility.cpp) and the record-clustered errors of a
/// stripe fit (stripe_clusters.cpp). Private to the fragility library.
#include "rocksweep/records/fragility.hpp"

namespace rocksweep::fit_detail {

/// ln Phi(z), accurate in both tails.
double log_cdf(double z);
/// phi(z) / Phi(z) = d ln Phi / dz.
double mills(double z);
/// `reached` runs reaching the state and `missed` not, at z = a + b ln x of P = Phi(z): their
/// log-likelihood and its first and second derivatives in z (counts of 0 contribute nothing).
struct ProbitTerm {
    double f = 0.0, d1 = 0.0, d2 = 0.0;
};
ProbitTerm probit_term(double z, double reached, double missed);
/// Fills the 95 % Wald intervals of `f` from its standard errors: on ln(median) and ln(beta),
/// so that both stay positive.
void intervals(FragilityFit& f);

}  // namespace rocksweep::fit_detail
