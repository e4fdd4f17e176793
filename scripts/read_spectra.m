function S = read_spectra(file)
%READ_SPECTRA  Read a rocksweep overturning-spectra HDF5 file (layout: docs/hdf5.md).
%
%   S = READ_SPECTRA(FILE) returns a struct with
%     S.file             the file name
%     S.omega_ratio      n_omega x 1, omega_p / p
%     S.amplitude_ratio  n_amp x 1,   a_p0 / (alpha g)
%     S.attrs            root attributes: block, pulse, n_cells, n_done, complete, ...
%     S.provenance       attributes of /provenance (version, config, ranks, ...)
%     S.scenario_names   cell array of the scenario field names, in config order
%     S.(scenario)       one struct per scenario with
%                          .name   the HDF5 group name (the field name may differ if the
%                                  group name is not a valid MATLAB identifier)
%                          .attrs  anchorage attributes (anchorage, theta_f_ratio, ...)
%                          .outcome, .max_rotation, .impacts, .t_overturn,
%                          .peak_force_ratio, .broken, .done   n_amp x n_omega matrices
%
%   S.(scenario).outcome(i_amp, i_omega) is the cell at amplitude_ratio(i_amp) and
%   omega_ratio(i_omega), as in the file's C-order [n_amp][n_omega] layout. MATLAB's h5read
%   reports HDF5 dimensions in reverse order (n_omega x n_amp), so every grid is transposed
%   here; do not transpose again.
%
%   Outcome codes: 0 safe, 1 overturned with impact, 2 overturned without impact,
%   255 not converged. Only cells with done == 1 hold results.
%
%   Example:
%     S = read_spectra('spectra.h5');
%     sc = S.(S.scenario_names{1});
%     imagesc(S.omega_ratio, S.amplitude_ratio, double(sc.outcome)); axis xy
%     xlabel('\omega_p / p'); ylabel('a_{p0} / (\alpha g)'); title(sc.name, 'Interpreter', 'none')
%
%   Needs MATLAB R2014a or later (h5read, h5readatt, h5info, matlab.lang.makeValidName).

    grids = {'outcome', 'max_rotation', 'impacts', 'impacts_total', 't_overturn', ...
             'peak_force_ratio', 'broken', 'mu_required', 'pivot_uplift', 'done'};
    reserved = {'file', 'omega_ratio', 'amplitude_ratio', 'attrs', 'provenance', ...
                'scenario_names'};

    S = struct();
    S.file = file;
    S.omega_ratio = h5read(file, '/axes/omega_ratio');
    S.amplitude_ratio = h5read(file, '/axes/amplitude_ratio');
    S.omega_ratio = S.omega_ratio(:);
    S.amplitude_ratio = S.amplitude_ratio(:);
    S.attrs = read_attributes(file, '/');
    S.provenance = struct();
    root = h5info(file, '/');
    if any(strcmp({root.Groups.Name}, '/provenance'))
        S.provenance = read_attributes(file, '/provenance');
    end

    n_amp = numel(S.amplitude_ratio);
    n_omega = numel(S.omega_ratio);

    spectra = h5info(file, '/spectra');
    groups = spectra.Groups;
    % Group listings come in name order; the `index` attribute restores the config order.
    order = zeros(1, numel(groups));
    for k = 1:numel(groups)
        order(k) = double(h5readatt(file, groups(k).Name, 'index'));
    end
    [~, perm] = sort(order);
    groups = groups(perm);

    S.scenario_names = {};
    for k = 1:numel(groups)
        path = groups(k).Name;                     % e.g. '/spectra/constant_2'
        slash = find(path == '/', 1, 'last');
        name = path(slash + 1:end);

        sc = struct();
        sc.name = name;
        sc.attrs = read_attributes(file, path);
        for g = 1:numel(grids)
            raw = h5read(file, [path '/' grids{g}]);   % n_omega x n_amp as MATLAB sees it
            sc.(grids{g}) = reshape(permute(raw, [2 1]), n_amp, n_omega);
        end

        field = matlab.lang.makeValidName(name);
        if any(strcmp(field, reserved))
            field = [field '_scenario'];
        end
        S.(field) = sc;
        S.scenario_names{end + 1} = field;
    end
end

function A = read_attributes(file, location)
% All attributes of one group as a struct; strings as char rows without their terminator.
    info = h5info(file, location);
    A = struct();
    for k = 1:numel(info.Attributes)
        attr = info.Attributes(k).Name;
        value = h5readatt(file, location, attr);
        A.(matlab.lang.makeValidName(attr)) = clean_value(value);
    end
end

function v = clean_value(v)
    if iscell(v) && numel(v) == 1
        v = v{1};
    end
    if ischar(v)
        v = reshape(v, 1, []);
        v = v(v ~= char(0));   % fixed-length strings may arrive with their null byte
    elseif isnumeric(v) && ~isscalar(v)
        v = v(:);
    end
end
