#pragma once
/// The work list of a sweep over a record suite: scenario x record x slenderness x block size x
/// intensity, one cell per index. Each record is scaled so that its intensity measure equals the
/// level (Vamvatsikos & Cornell's IDA scaling), and the block is reshaped at fixed density and
/// mass distribution (docs/suite.md, "Blocks"), so every cell depends only on its index.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "rocksweep/grid/sweep.hpp"
#include "rocksweep/motion/floor_filter.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/records/intensity.hpp"
#include "rocksweep/records/record_suite.hpp"

namespace rocksweep {

/// What the intensity axis measures. Levels are values of it; a record at level x is the record
/// times x / (its own measure).
enum class IntensityMeasure {
    pga_g,      ///< peak ground acceleration / standard g
    pgv_m_s,    ///< peak ground velocity [m/s]
    pga_ratio,  ///< PGA / (g tan alpha), the block's own g and alpha
    scale,      ///< the factor itself
    sa_g,       ///< Sa(T, zeta) of the ground / standard g, T and zeta the suite's
    pfa_g,      ///< peak floor acceleration / standard g: the motion of the scenario's own floor
};
/// "pga", "pgv", "pga-ratio", "scale", "sa", "pfa" (the option's words); throws InputError(field, text, ...).
IntensityMeasure parse_intensity_measure(const std::string& field, const std::string& text);
/// The dataset name of the measure: "pga_g", "pgv_m_s", "pga_ratio", "scale", "sa_g", "pfa_g".
std::string to_string(IntensityMeasure m);
const char* intensity_units(IntensityMeasure m);
const char* intensity_long_name(IntensityMeasure m);

/// Ground motions made where they are integrated (a synthetic model, docs/synthetic.md): the
/// suite keeps each one's name and measures, and the cells that need motion i make it again
/// from i, identically on every rank.
class MotionSource {
public:
    virtual ~MotionSource() = default;
    virtual std::size_t size() const = 0;
    /// Unique, letters, digits and '_' (a group name of the output's /records).
    virtual std::string name(std::size_t i) const = 0;
    virtual Record motion(std::size_t i) const = 0;
    /// Motion i as the suite keeps it: motion(i) without its horizontal samples. A source that
    /// can say this without making the motion overrides it.
    virtual Record described(std::size_t i) const {
        Record r = motion(i);
        r.ax_g = std::vector<double>();  // frees the samples: `= {}` would keep their capacity
        return r;
    }
    /// What makes them, on one line (stored in the output).
    virtual std::string describe() const = 0;
};

/// A record on one floor: the motion the block there stands on, and its measures.
struct FloorResponse {
    /// the floor's motion at the block's g and scale 1 (the ground's vertical); unset for a
    /// made motion, whose samples are made again in the cells
    Pulse pulse;
    double pfa_g = 0.0;               ///< peak floor acceleration / standard g (the PGA on the ground)
    std::vector<double> spectrum_g;   ///< 5 %-damped Sa at motion::floor_spectrum_periods() / standard g
};

/// One record of the suite as every cell sees it: its samples (standard g, the suite's own
/// scale applied) and its measures, read once.
struct SuiteMember {
    SuiteRecord entry;
    Record record;  ///< for a made motion, its description without samples (ax_g empty)
    IntensityMeasures measures;
    Pulse pulse;  ///< the record at the block's g and scale 1, whose samples every cell shares (may be unset)
    std::ptrdiff_t motion = -1;  ///< its index in SuiteSpec::motions; -1: a record read from a file
    double sa_g = 0.0;                 ///< Sa(T, zeta) of the ground at the suite's oscillator / standard g
    std::vector<FloorResponse> floors;  ///< one per SuiteSpec::floors
};

/// Where the blocks of a suite stand and the oscillator Sa is measured with: the floors (none:
/// the ground alone, the scenarios as configured; otherwise every scenario on every floor,
/// named SCENARIO@FLOOR) and Sa's T and zeta; and the made motions after the file's records
/// (may be null), which pass through the floors and are measured as a read record is.
struct SuiteMotions {
    std::vector<motion::Floor> floors;
    motion::Oscillator sa{1.0, 0.05};
    std::shared_ptr<const MotionSource> made;
    /// all: each made motion is made and measured now. none: none is made; their members hold
    /// no measures until records/made_measures.hpp fills them (a rank measures its share).
    enum class Measures { all, none } measures = Measures::all;
};

/// --check-sensitivity: each run is run again with its record's scale times (1 + scale_step)
/// and a tighter integration (the tolerance / tolerance_divisor; without a tolerance, the steps
/// per period times tolerance_divisor^(1/4), RK4's order); a run whose outcome or damage
/// state (the count of `damage_ratios`, theta_max / alpha, it reaches) differs is flagged
/// (CellResult::sensitive). docs/suite.md, "Sensitive runs".
struct SensitivityCheck {
    bool on = false;
    std::vector<double> damage_ratios;  ///< the suite's rotation damage states, increasing
    static constexpr double scale_step = 1e-9;
    static constexpr double tolerance_divisor = 100.0;
    /// The rerun's settings: `s` made tighter as above.
    static IntegratorSettings tighter(IntegratorSettings s);
    /// True where the two runs of one cell differ in outcome or damage state.
    bool differ(const CellResult& a, const CellResult& b) const;
};

struct SuiteSpec {
    Block block{};  ///< as configured; the size axis scales it
    Equations equations = Equations::nonlinear;
    double impact_threshold = 1e-3;
    double friction = 0.0;
    std::string suite_path;
    std::vector<std::string> metadata_columns;
    std::vector<SuiteMember> records;
    IntensityMeasure measure = IntensityMeasure::pga_g;
    Axis intensity;               ///< levels of `measure`
    std::vector<double> alphas_rad;  ///< slenderness angles alpha [rad]
    std::vector<double> radii_m;     ///< block sizes R [m]
    std::vector<Scenario> scenarios;  ///< anchorages of the configured block, scaled with it, on each floor
    std::shared_ptr<const MotionSource> motions;  ///< made motions after the file's records (may be null)
    std::vector<motion::Floor> floors;       ///< at least one ({ground} by default)
    std::vector<std::size_t> scenario_floor;  ///< the floor (index into floors) of each scenario
    motion::Oscillator sa{1.0, 0.05};        ///< the oscillator of the sa_g measure
    SensitivityCheck sensitivity;            ///< off by default

    std::size_t cells_per_scenario() const { return records.size() * alphas_rad.size() * radii_m.size() * intensity.points; }
    std::size_t cell_count() const { return cells_per_scenario() * scenarios.size(); }
    /// Where cell `index` sits on the axes, and back:
    /// index = (((scenario * n_record + record) * n_alpha + alpha) * n_radius + radius) * n_level + level.
    struct Coordinates {
        std::size_t scenario = 0, record = 0, alpha = 0, radius = 0, level = 0;
    };
    Coordinates coordinates(std::size_t index) const;
    std::size_t index(const Coordinates& c) const;
    /// Cell `index`; `ground` (the cell's own motion on its scenario's floor, at the block's g
    /// and scale 1) must be given for a made motion, whose samples the spec does not hold.
    CellModel cell(std::size_t index, const Pulse* ground = nullptr) const;
    /// The floor (index into floors) scenario `s` stands on; 0 when none is recorded.
    std::size_t floor_of(std::size_t s) const { return scenario_floor.empty() ? 0 : scenario_floor.at(s); }
    /// The factor record `r` is multiplied by at intensity level `level` on blocks of slenderness
    /// alphas_rad[alpha] (only PGA / (g tan alpha) depends on it) standing on floors[floor]
    /// (only PFA depends on it). The ground and every floor's motion scale together: the
    /// building is linear.
    double scale_factor(std::size_t r, std::size_t alpha, std::size_t level, std::size_t floor = 0) const;
    /// The configured block reshaped to slenderness alpha and size R (reshaped_block).
    Block block_of(double alpha_rad, double radius_m) const;
};

/// Reads the suite file and every record in it (each record's own checks apply), then adds the
/// made motions of `motions` (either may be absent: an empty path, a null source); passes each
/// through every floor of `motions` and measures it there (a made motion's samples are then
/// dropped). `scenarios` are those of the configured block; empty `alphas_rad` or `radii_m`
/// mean the block's own. Throws InputError naming the option or the suite line.
SuiteSpec make_suite_spec(const std::string& suite_path, const Block& block, std::vector<Scenario> scenarios,
                          IntensityMeasure measure, Axis intensity, std::vector<double> radii_m,
                          std::vector<double> alphas_rad = {}, SuiteMotions motions = {});

/// `ground` as it reaches `floor`: the horizontal component through the floor's filters, the
/// vertical as it is (the building is taken as rigid vertically; docs/physics.md), both at
/// motion::floor_oversampling samples per step of the record.
Record on_floor(const Record& ground, const motion::Floor& floor);

/// Computes cells [first, first + count) of `spec` into `out`; a made motion is made once for
/// the consecutive cells that share it. With spec.sensitivity.on each cell is run twice and
/// its `sensitive` flag set from the pair; the first run's results are kept.
void compute_suite_cells(const SuiteSpec& spec, const IntegratorSettings& settings, std::size_t first,
                         std::size_t count, CellResult* out, int lanes = 8);

}  // namespace rocksweep
