function R = read_risk(file, scenario)
%READ_RISK  Read one anchorage scenario of a rocksweep risk file (rocksweep risk; docs/risk.md).
%
%   R = READ_RISK(FILE) reads the first scenario (in the suite's order), R = READ_RISK(FILE, NAME) the
%   scenario NAME ('free', 'constant_tf1', ...). R holds
%     R.file, R.scenario, R.scenario_names (in the suite's order), R.floor (the suite's floor
%                          the scenario's blocks stood on: 'ground', 'f2', ...)
%     R.attrs              root attributes read by name: hazard_measure, hazard_units,
%                          hazard_file, hazard_format, suite_file, intensity_measure,
%                          exposure_years, investigation_time_years, hazard_tail_rule
%     R.hazard_intensity, R.hazard_rate    the hazard curve's points [unit, 1/yr]
%     R.states             damage-state names (cell array); R.alpha_rad, R.radius_m;
%                          R.intensity (the deaggregation's points), R.level (the suite's levels)
%     R.rate_fit, R.rate_fit_lo, R.rate_fit_hi, R.probability_fit, R.return_period_fit,
%     R.share_below_fit, R.share_above_fit, and the same *_empirical, R.median_intensity, R.beta,
%     R.fit_status         [state, alpha, radius]: R.rate_fit(s, a, j) is the annual rate of
%                          state R.states{s} at R.alpha_rad(a), R.radius_m(j)
%     R.deaggregation_fit, R.deaggregation_empirical   [state, alpha, radius, intensity]
%     R.fraction           [state, alpha, radius, level]
%
%   Every array is permuted back to the file's (C) index order, as h5py and numpy see it.
%   Runs in MATLAB and in GNU Octave with the netcdf package (ncinfo, ncread, ncreadatt only).
%
%   Example:
%     R = read_risk('results/risk.h5', 'free');
%     s = find(strcmp(R.states, 'overturning'));
%     fprintf('%.3g per year, P = %.3g in %g years\n', R.rate_fit(s, 1, 1), ...
%             R.probability_fit(s, 1, 1), R.attrs.exposure_years);

    if exist('OCTAVE_VERSION', 'builtin') && ~exist('ncread', 'file'), pkg load netcdf; end
    R = struct('file', file);
    if ~strcmp(ncreadatt(file, '/', 'kind'), 'risk')
        error('read_risk:layout', '%s: not a rocksweep risk file (no root attribute kind = ''risk'')', file);
    end
    for name = {'hazard_measure', 'hazard_units', 'hazard_file', 'hazard_format', 'suite_file', ...
                'intensity_measure', 'exposure_years', 'investigation_time_years', 'hazard_tail_rule'}
        R.attrs.(name{1}) = ncreadatt(file, '/', name{1});
    end
    info = ncinfo(file, '/risk');
    % The suite's order (its index attribute: free, constant, adaptive; ground, then upstairs).
    order = zeros(1, numel(info.Groups));
    for k = 1:numel(info.Groups)
        for a = info.Groups(k).Attributes
            if strcmp(a.Name, 'index'), order(k) = double(a.Value); end
        end
    end
    [~, perm] = sort(order);
    R.scenario_names = {info.Groups(perm).Name};
    if nargin < 2
        scenario = R.scenario_names{1};
    elseif ~any(strcmp(R.scenario_names, scenario))
        error('read_risk:scenario', '%s: no scenario %s (the file has %s)', file, scenario, strjoin(R.scenario_names, ', '));
    end
    R.scenario = scenario;
    try
        R.floor = ncreadatt(file, ['/risk/' scenario], 'floor');
    catch
        R.floor = 'ground';  % a risk file written before floors were named in it
    end
    R.hazard_intensity = ncread(file, '/hazard/intensity');
    R.hazard_rate = ncread(file, '/hazard/rate');
    g = ['/risk/' scenario];
    R.states = strsplit(ncreadatt(file, [g '/damage_state'], 'flag_meanings'), ' ');
    for axis = {'alpha_rad', 'radius_m', 'intensity', 'level'}
        R.(axis{1}) = ncread(file, [g '/' axis{1}]);
    end
    names = {};
    for src = {'fit', 'empirical'}
        s = src{1};
        names = [names, {['rate_' s], ['rate_' s '_lo'], ['rate_' s '_hi'], ['probability_' s], ...
                         ['return_period_' s], ['share_below_' s], ['share_above_' s], ['deaggregation_' s]}];
    end
    for v = [names, {'median_intensity', 'beta', 'fit_status', 'fraction'}]
        x = ncread(file, [g '/' v{1}]);
        % ncread reverses the dimensions; a trailing singleton is dropped, so pad to the rank.
        rank = 3 + any(strcmp(v{1}, {'deaggregation_fit', 'deaggregation_empirical', 'fraction'}));
        R.(v{1}) = permute(x, rank:-1:1);
    end
end
