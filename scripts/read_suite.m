function S = read_suite(file, scenario)
%READ_SUITE  Read one anchorage scenario of a rocksweep record-suite file (layout: docs/suite.md).
%
%   S = READ_SUITE(FILE) reads the first scenario (in config order), S = READ_SUITE(FILE, NAME)
%   the scenario NAME ('free', 'constant_tf1', 'adaptive_rho0.1', ...). S holds
%     S.file, S.attrs      the file name and its root attributes (block, intensity_measure,
%                          intensity_units, complete, ...)
%     S.scenario_names     every scenario of the file, in config order (group names)
%     S.scenario           the group name read; S.scenario_attrs its attributes (anchorage, ...)
%     S.record_names       the record names in suite order (a column cell array)
%     S.record             0, 1, ..., n_record-1;  S.alpha_rad [rad];  S.radius_m [m];
%                          S.intensity (the levels)
%     S.outcome, S.max_rotation, S.impacts, S.impacts_total, S.t_overturn,
%     S.peak_force_ratio, S.broken, S.mu_required, S.pivot_uplift, S.done
%                          arrays (record, alpha, radius, level) of the file's types (uint8,
%                          int32, double): S.outcome(i, a, j, k) is record i at S.alpha_rad(a),
%                          S.radius_m(j) and level S.intensity(k), the element
%                          [i-1, a-1, j-1, k-1] of h5py and numpy; S.sensitive too (uint8, 1:
%                          flagged) in a file of suite --check-sensitivity (docs/suite.md)
%     S.records            per-record measures (pga_g, pgv_m_s, ..., [record]) and
%                          scale_factor, pga_scaled_g [record, alpha, level]; S.records.metadata(i) the
%                          attributes of record i (name, event, station, file, ...)
%     S.records.sa_g       Sa(T, zeta) of each record as read [g], S.records.sa_period_s and
%                          S.records.sa_damping its T [s] and zeta (absent in files before them)
%     S.floors             one element per floor (docs/suite.md, "Floors"; empty before floors):
%                          .name, .floor (its definition), .pfa_g, .pfa_over_pga [record],
%                          .spectrum_g [record, period], .median_spectrum_g, .period_s [period],
%                          .scale_factor [record, alpha, level], .median_pfa_g,
%                          .median_pfa_over_pga; S.scenario_attrs.floor names the scenario's
%     S.units              the units attribute of each result array that has one
%     S.overturning        [] unless the sweep is complete, else a struct of first_intensity,
%                          first_pga_g, below_intensity, safe_above [record, alpha, radius]
%     S.fragility          [] unless complete, else a struct with .states (cell array of names),
%                          .rotation_ratios, fraction, fraction_lo, fraction_hi, exceed, total
%                          [state, alpha, radius, level], median, beta, ...,
%                          cov_ln_median_beta (absent in files before it), fit_status
%                          [state, alpha, radius]
%                          and .fit_status_names (cell array of the fit_status meanings);
%                          .sensitive_runs [state, alpha, radius] with --check-sensitivity
%
%   Outcome codes: 0 safe, 1 overturned with impact, 2 without impact, 255 not converged.
%   ncread lists dimensions in reverse (column-major) order; every array is permuted back here
%   to the file's order: do not transpose again.
%
%   Example:
%     S = read_suite('results/suite.h5', 'free');
%     plot(S.radius_m, squeeze(S.overturning.first_pga_g(:, 1, :))'); xlabel('R [m]');
%     ylabel('first overturning PGA [g]')   % at the first alpha
%
%   Runs in MATLAB and in GNU Octave with the netcdf package, with ncinfo, ncread and ncreadatt
%   only. Octave's ncinfo (netcdf package 1.0.16) cannot list the whole file: it fails with
%   "incompatible fields in struct assignment" when sibling groups differ in whether they hold
%   variables (/records does, /provenance and /suite do not). Each group is therefore listed on
%   its own, and the root attributes, if the whole file cannot be listed, read by name.

    load_netcdf();
    S = struct();
    S.file = file;
    S.attrs = root_attributes(file);
    if ~isfield(S.attrs, 'kind') || ~strcmp(S.attrs.kind, 'suite')
        error('read_suite:layout', '%s: not a rocksweep suite file (no root attribute kind = ''suite'')', file);
    end

    suite = ncinfo(file, '/suite');
    groups = suite.Groups;
    order = zeros(1, numel(groups));
    for k = 1:numel(groups)
        a = nc_attributes(groups(k).Attributes);
        order(k) = double(a.index);
    end
    [~, perm] = sort(order);
    S.scenario_names = {groups(perm).Name};
    if nargin < 2
        scenario = S.scenario_names{1};
    elseif ~any(strcmp(S.scenario_names, scenario))
        error('read_suite:scenario', '%s: no scenario %s (the file has %s)', file, scenario, ...
              strjoin(S.scenario_names, ', '));
    end

    S.record_names = strsplit(ncreadatt(file, '/records/record', 'flag_meanings'), ' ')';
    S.records = read_variables(file, '/records', struct('units', struct()));
    info = ncinfo(file, '/records');
    meta = struct('name', S.record_names);
    for i = 1:numel(S.record_names)
        k = find(strcmp({info.Groups.Name}, S.record_names{i}), 1);
        if ~isempty(k)
            a = nc_attributes(info.Groups(k).Attributes);
            for f = fieldnames(a)'
                meta(i).(f{1}) = a.(f{1});
            end
        end
    end
    S.records.metadata = meta;
    if isfield(S.records, 'sa_g')
        S.records.sa_period_s = ncreadatt(file, '/records/sa_g', 'period_s');
        S.records.sa_damping = ncreadatt(file, '/records/sa_g', 'damping');
    end
    S.floors = read_floors(file);

    path = ['/suite/' scenario];
    g = ncinfo(file, path);
    S.scenario = scenario;
    S.scenario_attrs = nc_attributes(g.Attributes);
    S.units = struct();
    S = read_variables(file, path, S);
    S.overturning = [];
    S.fragility = [];
    sub = {};
    if isfield(g, 'Groups') && ~isempty(g.Groups)
        sub = {g.Groups.Name};
    end
    if any(strcmp(sub, 'overturning'))
        S.overturning = read_variables(file, [path '/overturning'], struct('units', struct()));
    end
    if any(strcmp(sub, 'fragility'))
        fr = read_variables(file, [path '/fragility'], struct('units', struct()));
        fr.states = strsplit(ncreadatt(file, [path '/fragility/damage_state'], 'flag_meanings'), ' ')';
        fr.rotation_ratios = ncreadatt(file, [path '/fragility/damage_state'], 'rotation_ratios');
        fr.rotation_ratios = fr.rotation_ratios(:);
        meanings = strsplit(ncreadatt(file, [path '/fragility/fit_status'], 'flag_meanings'), ' ');
        fr.fit_status_names = reshape(meanings(double(fr.fit_status) + 1), size(fr.fit_status));
        S.fragility = fr;
    end
end

function F = read_floors(file)
% Each /floors/<floor> group: its arrays and attributes, one struct element per floor.
    F = struct('name', {});
    try
        info = ncinfo(file, '/floors');
    catch
        return  % a file written before floors
    end
    for k = 1:numel(info.Groups)
        name = info.Groups(k).Name;
        path = ['/floors/' name];
        fl = read_variables(file, path, struct('name', name));
        for a = {'floor', 'median_pfa_g', 'median_pfa_over_pga'}
            fl.(a{1}) = ncreadatt(file, path, a{1});
        end
        F = add_element(F, fl);
    end
end

function A = add_element(A, s)
% s appended to the struct array A (a field new to A is added to every element).
    n = numel(A) + 1;
    for f = fieldnames(s)'
        A(n).(f{1}) = s.(f{1});
    end
end

function T = read_variables(file, path, T)
% Every variable of the group at `path` into T, in the file's (C) index order, and the units
% of those that have one into T.units (when T has that field).
    info = ncinfo(file, path);
    for v = 1:numel(info.Variables)
        var = info.Variables(v);
        x = ncread(file, [path '/' var.Name]);
        n = numel(var.Dimensions);
        if n > 1, x = permute(x, n:-1:1); else, x = x(:); end
        T.(var.Name) = x;
        a = nc_attributes(var.Attributes);
        if isfield(T, 'units') && isfield(a, 'units')
            T.units.(var.Name) = a.units;
        end
    end
end

function A = root_attributes(file)
% The root attributes: from ncinfo of the whole file where it works (MATLAB), else by name.
    try
        info = ncinfo(file);
        A = nc_attributes(info.Attributes);
        return
    catch
    end
    names = {'title', 'format_version', 'kind', 'half_width_m', 'half_height_m', 'radius_m', 'alpha_rad', ...
             'p_rad_s', 'e', 'inertia_ratio', 'mass_kg', 'gravity_m_s2', 'intensity_measure', ...
             'intensity_units', 'intensity_long_name', 'suite_file', 'method', 'steps_per_period', ...
             'max_steps', 'energy_stop', 'impact_threshold', 'equations', 'n_cells', 'n_done', 'complete'};
    A = struct();
    for k = 1:numel(names)
        try
            a = nc_attributes(struct('Name', names{k}, 'Value', ncreadatt(file, '/', names{k})));
            A.(names{k}) = a.(names{k});
        catch
        end
    end
end
