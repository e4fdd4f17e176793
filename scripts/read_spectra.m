function S = read_spectra(file)
%READ_SPECTRA  Read a rocksweep overturning-spectra file (layout: docs/hdf5.md).
%
%   S = READ_SPECTRA(FILE) returns a struct with
%     S.file             the file name
%     S.axes             the grid's axis names in the file's order, e.g.
%                        {'amplitude_ratio', 'omega_ratio'}
%     S.<axis>           each axis as a column vector (S.amplitude_ratio, S.omega_ratio)
%     S.attrs            root attributes: block, pulse, n_cells, n_done, complete, ...
%     S.provenance       attributes of /provenance (version, config, ranks, ...)
%     S.scenario_names   cell array of the scenario field names, in config order
%     S.(scenario)       one struct per scenario with
%                          .name   the group name (the field name may differ if the group
%                                  name is not a valid identifier: constant_tf0.5 becomes
%                                  constant_tf0_5)
%                          .attrs  anchorage attributes (anchorage, theta_f_ratio, ...)
%                          .units  the units attribute of each dataset that has one
%                          .outcome, .max_rotation, .impacts, .impacts_total, .t_overturn,
%                          .peak_force_ratio, .broken, .mu_required, .pivot_uplift, .done
%                                  arrays over the axes, of the file's types (uint8, int32,
%                                  double), and the scenario's own copy of each axis
%
%   Arrays come in the file's index order: S.(scenario).outcome(i_amp, i_omega) is the cell
%   at amplitude_ratio(i_amp) and omega_ratio(i_omega), the element [i_amp, i_omega] of
%   h5py and numpy, whatever axes the grid has. ncread lists netCDF dimensions in reverse
%   (column-major) order; every array is permuted back here: do not transpose again.
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
%   Runs in MATLAB (R2012a or later) and in GNU Octave with the netcdf package
%   (Debian: octave-netcdf; then "pkg load netcdf", done here when needed): it uses only
%   ncinfo, ncread and their attribute values, which both have.

    load_netcdf();
    reserved = {'file', 'axes', 'attrs', 'provenance', 'scenario_names'};

    info = ncinfo(file);
    S = struct();
    S.file = file;
    S.axes = {};
    S.attrs = nc_attributes(info.Attributes);
    S.provenance = struct();
    prov = child_group(info, 'provenance');
    if ~isempty(prov)
        S.provenance = nc_attributes(prov.Attributes);
    end

    spectra = child_group(info, 'spectra');
    if isempty(spectra)
        error('read_spectra:layout', '%s: no /spectra group: not a rocksweep spectra file', file);
    end
    groups = spectra.Groups;
    % Groups come in name order; the `index` attribute restores the config order.
    order = zeros(1, numel(groups));
    for k = 1:numel(groups)
        a = nc_attributes(groups(k).Attributes);   % MATLAB cannot index a call's result
        order(k) = double(a.index);
    end
    [~, perm] = sort(order);
    groups = groups(perm);

    S.scenario_names = {};
    for k = 1:numel(groups)
        g = groups(k);
        sc = struct();
        sc.name = g.Name;
        sc.attrs = nc_attributes(g.Attributes);
        sc.units = struct();
        for v = 1:numel(g.Variables)
            var = g.Variables(v);
            dims = {var.Dimensions.Name};          % fastest first, as ncread returns them
            sc.(var.Name) = file_order(ncread(file, ['/spectra/' g.Name '/' var.Name]), numel(dims));
            a = nc_attributes(var.Attributes);
            if isfield(a, 'units')
                sc.units.(var.Name) = a.units;
            end
            if numel(dims) == 1 && strcmp(dims{1}, var.Name)
                S.(var.Name) = sc.(var.Name);       % an axis: the same in every scenario
            elseif isempty(S.axes)
                S.axes = fliplr(dims);
            end
        end
        field = matlab.lang.makeValidName(g.Name);
        if any(strcmp(field, [reserved, S.axes]))
            field = [field '_scenario'];
        end
        S.(field) = sc;
        S.scenario_names{end + 1} = field;
    end
end

function x = file_order(x, n)
% The array in the file's (C) index order: ncread gives the n dimensions reversed.
    if n <= 1
        x = x(:);
    else
        x = permute(x, n:-1:1);
    end
end

function g = child_group(info, name)
    g = [];
    if ~isfield(info, 'Groups') || isempty(info.Groups)
        return
    end
    k = find(strcmp({info.Groups.Name}, name), 1);
    if ~isempty(k)
        g = info.Groups(k);
    end
end
