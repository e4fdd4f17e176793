// Parameter axes of a spectra grid: how they are written, and that each point of them is the
// sweep with that parameter set, cell for cell and bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/grid/block_family.hpp"
#include "rocksweep/grid/parameter_axis.hpp"
#include "rocksweep/grid/sweep.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "smatteo_case.hpp"

namespace rocksweep {
namespace {

using testing::kSMatteo;
using testing::kSMatteoStrength;

std::string refusal(const std::string& text) {
    try {
        parse_parameter_axis("axis", text);
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "axis");
        EXPECT_EQ(e.value(), text);
        return e.allowed();
    }
    return "(accepted)";
}

TEST(ParameterAxis, ReadsARangeAListAndDashedNames) {
    const ParameterAxis a = parse_parameter_axis("axis", "phase-rad=0:1:3");
    EXPECT_EQ(a.parameter, Parameter::phase);
    EXPECT_EQ(a.values, (std::vector<double>{0.0, 0.5, 1.0}));
    const ParameterAxis b = parse_parameter_axis("axis", "restitution=0.8,0.85,0.9");
    EXPECT_EQ(b.parameter, Parameter::restitution);
    EXPECT_EQ(b.values, (std::vector<double>{0.8, 0.85, 0.9}));
    // Both ends exactly as written, whatever the spacing rounds to.
    const ParameterAxis c = parse_parameter_axis("axis", "radius_m=0.3:3.1:7");
    EXPECT_EQ(c.values.front(), 0.3);
    EXPECT_EQ(c.values.back(), 3.1);
    EXPECT_EQ(std::string(parameter_info(Parameter::radius).units), "m");
}

TEST(ParameterAxis, RefusesWhatItCannotRead) {
    EXPECT_NE(refusal("colour=1:2:3").find("an axis named one of phase_rad"), std::string::npos);
    EXPECT_NE(refusal("phase_rad").find("NAME=LO:HI:POINTS or NAME=V1,V2"), std::string::npos);
    EXPECT_NE(refusal("phase_rad=0:1").find("NAME=LO:HI:POINTS or NAME=V1,V2"), std::string::npos);
    EXPECT_NE(refusal("phase_rad=1:0:3").find("LO < HI"), std::string::npos);
    EXPECT_NE(refusal("phase_rad=0:1:1").find("2 to 100000 POINTS"), std::string::npos);
    EXPECT_NE(refusal("phase_rad=0:1:2.5").find("2 to 100000 POINTS"), std::string::npos);
    EXPECT_NE(refusal("restitution=0.9,0.8").find("strictly increasing"), std::string::npos);
    EXPECT_NE(refusal("restitution=0.8,0.8").find("strictly increasing"), std::string::npos);
    EXPECT_NE(refusal("vertical_g=0:1.5:3").find("vertical_g values in [-0.99, 0.99]"), std::string::npos);
    EXPECT_NE(refusal("restitution=0,0.5").find("restitution values in (0, 1]"), std::string::npos);
    EXPECT_NE(refusal("radius_m=nan,1").find("NAME=LO:HI:POINTS"), std::string::npos);
}

SweepSpec small_spec() {
    SweepSpec s;
    s.block = kSMatteo;
    s.omega_ratio = Axis{2.0, 6.0, 3};
    s.amplitude_ratio = Axis{2.0, 8.0, 4};
    s.scenarios.push_back({"free", free_anchorage(), 0.0, 1.0});
    s.scenarios.push_back({"constant_tf1", constant_anchorage(kSMatteo, kSMatteoStrength, kSMatteo.alpha_rad), 1.0, 1.0});
    return s;
}

std::vector<CellResult> run(const SweepSpec& s, std::size_t first, std::size_t count) {
    std::vector<CellResult> r(count);
    compute_cells(s, IntegratorSettings{}, first, count, r.data());
    return r;
}

TEST(SweepPlanes, EachPointOfTheAxesIsTheSweepWithThoseValues) {
    SweepSpec swept = small_spec();
    swept.axes.push_back(parse_parameter_axis("axis", "phase_rad=0,1.5707963267948966"));
    swept.axes.push_back(parse_parameter_axis("axis", "restitution=0.85,0.9"));
    ASSERT_EQ(swept.planes_per_scenario(), 4u);
    ASSERT_EQ(swept.cells_per_scenario(), 4u * 12u);
    ASSERT_EQ(swept.cell_count(), 2u * 48u);

    for (std::size_t plane = 0; plane < 4; ++plane) {
        SweepSpec plain = small_spec();  // the same plane as a sweep of its own
        plain.phase = plane / 2 == 0 ? 0.0 : 1.5707963267948966;
        plain.block.e = plane % 2 == 0 ? 0.85 : 0.9;
        const SweepSpec::Plane p = swept.plane(plane);
        EXPECT_EQ(p.at, (std::vector<std::size_t>{plane / 2, plane % 2}));
        EXPECT_EQ(p.block.e, plain.block.e);
        for (std::size_t s = 0; s < 2; ++s) {
            const std::vector<CellResult> a = run(swept, s * 48 + plane * 12, 12), b = run(plain, s * 12, 12);
            for (std::size_t i = 0; i < 12; ++i)
                EXPECT_TRUE(bitwise_equal(a[i], b[i])) << "scenario " << s << ", plane " << plane << ", cell " << i;
        }
    }
}

TEST(SweepPlanes, WithoutAxesTheGridIsTheTwoDimensionalOne) {
    const SweepSpec s = small_spec();
    EXPECT_EQ(s.planes_per_scenario(), 1u);
    EXPECT_EQ(s.cells_per_scenario(), s.plane_cells());
    EXPECT_TRUE(s.plane(0).at.empty());
    EXPECT_FALSE(s.plane(0).reshaped);
}

// A block scaled at fixed shape with its anchorage's ratios (F_u / (m g), theta_f / alpha) under
// pulses at the same omega_p / p and a_p0 / (alpha g) obeys the same dimensionless equation
// (Makris & Vassiliou's similarity): its response is the same to rounding, whatever its size.
TEST(SweepPlanes, ASizeAxisKeepsTheDimensionlessResponse) {
    SweepSpec swept = small_spec();
    swept.axes.push_back({Parameter::radius, {0.5, kSMatteo.radius_m, 4.0}, "radius_m=0.5,R,4"});
    const std::vector<CellResult> r = run(swept, 0, swept.cell_count());
    const std::size_t per = swept.cells_per_scenario(), plane = swept.plane_cells();
    int compared = 0;
    for (std::size_t s = 0; s < 2; ++s)
        for (std::size_t i = 0; i < plane; ++i) {
            const CellResult& mid = r[s * per + plane + i];
            for (std::size_t k : {std::size_t{0}, std::size_t{2}}) {
                const CellResult& other = r[s * per + k * plane + i];
                EXPECT_EQ(other.outcome, mid.outcome) << "scenario " << s << ", cell " << i;
                EXPECT_EQ(other.impacts, mid.impacts);
                if (mid.outcome == Outcome::safe) {
                    EXPECT_NEAR(other.max_rotation, mid.max_rotation, 1e-9 * mid.max_rotation) << "cell " << i;
                    ++compared;
                }
            }
        }
    EXPECT_GE(compared, 8);
    // The plane at the block's own R is the block itself, anchorage and all.
    const SweepSpec::Plane own = swept.plane(1);
    EXPECT_FALSE(own.reshaped);
    const Block big = swept.plane(2).block;
    EXPECT_NEAR(big.mass_kg / kSMatteo.mass_kg, std::pow(4.0 / kSMatteo.radius_m, 3), 1e-12);
    EXPECT_EQ(big.alpha_rad, kSMatteo.alpha_rad);
    const Anchorage a = anchorage_on(swept.scenarios[1], kSMatteo, big);
    EXPECT_NEAR(a.strength_n / (big.mass_kg * big.gravity), 0.4, 1e-14);
    EXPECT_NEAR(a.theta_f_rad, kSMatteo.alpha_rad, 1e-15);
}

TEST(SweepPlanes, AStrengthAxisSetsFuOverMgOfEveryAnchorage) {
    SweepSpec swept = small_spec();
    swept.axes.push_back(parse_parameter_axis("axis", "strength_ratio=0.2,0.8"));
    const SweepSpec::Plane p = swept.plane(1);
    ASSERT_TRUE(p.anchorage.strength_ratio);
    const Anchorage a = anchorage_on(swept.scenarios[1], kSMatteo, p.block, p.anchorage);
    EXPECT_NEAR(a.strength_n, 0.8 * kSMatteo.mass_kg * kSMatteo.gravity, 1e-9);
    EXPECT_NEAR(a.theta_f_rad, kSMatteo.alpha_rad, 1e-15);  // theta_f / alpha kept: K doubles with F_u
    EXPECT_NEAR(a.k_max, 2.0 * swept.scenarios[1].anchorage.k_max, 1e-9 * a.k_max);
}

SweepSpec anchored_spec(double theta_f_ratio, double kmin_ratio) {
    SweepSpec s = small_spec();
    s.scenarios.pop_back();
    s.scenarios.push_back({"constant", constant_anchorage(kSMatteo, kSMatteoStrength, theta_f_ratio * kSMatteo.alpha_rad),
                           theta_f_ratio, 1.0});
    s.scenarios.push_back({"adaptive",
                           adaptive_anchorage(kSMatteo, kSMatteoStrength, theta_f_ratio * kSMatteo.alpha_rad, kmin_ratio),
                           theta_f_ratio, kmin_ratio});
    return s;
}

// theta_f / alpha and K_min / K_max as axes give the bits of the scenario lists they replace.
TEST(SweepPlanes, AnchorageAxesAreTheScenariosTheyReplace) {
    SweepSpec swept = anchored_spec(1.0, 0.5);
    swept.axes.push_back(parse_parameter_axis("axis", "theta_f_ratio=0.5,2"));
    swept.axes.push_back(parse_parameter_axis("axis", "kmin_ratio=0.1,1"));
    const std::size_t per = swept.cells_per_scenario();
    for (std::size_t plane = 0; plane < 4; ++plane) {
        const double tf = plane / 2 == 0 ? 0.5 : 2.0, rho = plane % 2 == 0 ? 0.1 : 1.0;
        const SweepSpec plain = anchored_spec(tf, rho);
        for (std::size_t s = 0; s < 3; ++s) {
            const std::vector<CellResult> a = run(swept, s * per + plane * 12, 12), b = run(plain, s * 12, 12);
            for (std::size_t i = 0; i < 12; ++i)
                EXPECT_TRUE(bitwise_equal(a[i], b[i])) << "scenario " << s << ", plane " << plane << ", cell " << i;
        }
    }
}

TEST(SweepPlanes, AStiffnessAxisSetsKAndTheFractureAngleFollowsFromFu) {
    SweepSpec swept = anchored_spec(1.0, 0.5);
    swept.axes.push_back(parse_parameter_axis("axis", "stiffness_n_m=2e4,2e5"));
    const SweepSpec::Plane p = swept.plane(1);
    const Anchorage c = anchorage_on(swept.scenarios[1], kSMatteo, p.block, p.anchorage);
    EXPECT_EQ(c.k_max, 2e5);
    EXPECT_NEAR(4.0 * kSMatteo.half_width_m() * std::tan(c.theta_f_rad / 2) * c.k_max, kSMatteoStrength, 1e-9 * kSMatteoStrength);
    const Anchorage a = anchorage_on(swept.scenarios[2], kSMatteo, p.block, p.anchorage);
    EXPECT_NEAR(a.k_max, 2e5, 1e-9 * 2e5);  // K_max, its theta_f from F_u, K_min = 0.5 K_max
    EXPECT_NEAR(a.k_min, 0.5 * a.k_max, 1e-15 * a.k_max);
    EXPECT_EQ(a.theta_f_rad, c.theta_f_rad);
}

// The pulse family as a categorical axis: codes in the order given, named for the file, and each
// plane the sweep of that family.
TEST(SweepPlanes, APulseFamilyAxisIsTheSweepOfEachFamily) {
    SweepSpec swept = small_spec();
    swept.pulse_cycles = 2;
    swept.axes.push_back(parse_parameter_axis("axis", "pulse_family=ricker,one-sine,cycloidal-c"));
    EXPECT_EQ(swept.axes[0].values, (std::vector<double>{6.0, 0.0, 4.0}));
    EXPECT_EQ(flag_meanings(swept.axes[0]), "ricker one-sine cycloidal-c");
    const PulseFamily families[] = {PulseFamily::ricker, PulseFamily::one_sine, PulseFamily::cycloidal_c};
    for (std::size_t plane = 0; plane < 3; ++plane) {
        SweepSpec plain = small_spec();
        plain.pulse_family = families[plane];
        plain.pulse_cycles = 2;
        for (std::size_t s = 0; s < 2; ++s) {
            const std::vector<CellResult> a = run(swept, s * 36 + plane * 12, 12), b = run(plain, s * 12, 12);
            for (std::size_t i = 0; i < 12; ++i)
                EXPECT_TRUE(bitwise_equal(a[i], b[i])) << to_string(families[plane]) << ", scenario " << s << ", cell " << i;
        }
    }
    EXPECT_NE(refusal("pulse_family=ricker,sine").find("NAME one of one-sine, n-sine"), std::string::npos);
    EXPECT_NE(refusal("pulse_family=ricker,ricker").find("each family once"), std::string::npos);
}

// The spectrum's axes in the pulse's own terms: T_p [s] and a_p0 / g set the pulse whatever the
// block, so blocks of another size see the same pulse (and no longer the same ratios).
TEST(SweepPlanes, PeriodAndPgaAxesSetThePulseWhateverTheBlock) {
    SweepSpec swept = small_spec();
    swept.frequency_axis = FrequencyAxis::period_s;
    swept.amplitude_axis = AmplitudeAxis::pga_g;
    swept.omega_ratio = Axis{0.5, 1.5, 3};    // T_p [s]
    swept.amplitude_ratio = Axis{0.1, 0.4, 4};  // a_p0 / g
    swept.axes.push_back({Parameter::radius, {kSMatteo.radius_m, 4.0}, "radius_m=R,4"});
    for (std::size_t plane : {std::size_t{0}, std::size_t{1}}) {
        const CellModel c = swept.cell(plane * 12 + 2 * 3 + 1);  // a_p0 = 0.3 g, T_p = 1 s
        EXPECT_EQ(c.pulse.ax_g, 0.30000000000000004);           // lo + (hi - lo) 2/3, as Axis::at gives it
        EXPECT_EQ(c.pulse.omega, 2.0 * M_PI / 1.0);
    }
    EXPECT_EQ(swept.cell(0).pulse.ax_g, 0.1);
    EXPECT_EQ(swept.cell(2).pulse.omega, 2.0 * M_PI / 1.5);
}

TEST(SweepPlanes, ARestitutionAboveHousnersValueOfAReshapedBlockIsRefused) {
    SweepSpec swept = small_spec();
    swept.axes.push_back(parse_parameter_axis("axis", "alpha_rad=0.1,0.3"));
    swept.axes.push_back(parse_parameter_axis("axis", "restitution=0.9"));
    EXPECT_NO_THROW(swept.plane(0));  // Housner's e at alpha = 0.1: 0.985
    try {
        swept.plane(1);  // at 0.3: 1 - 2 sin^2(0.3) / (4/3) = 0.869
        ADD_FAILURE() << "e = 0.9 accepted above Housner's 0.869";
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "block.restitution");
        EXPECT_NE(e.allowed().find("Housner's value 0.869"), std::string::npos) << e.allowed();
    }
}

}  // namespace
}  // namespace rocksweep
