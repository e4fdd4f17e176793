function H = read_history(file)
%READ_HISTORY  Read a rocksweep time-history file written by `rocksweep simulate -o NAME.h5`
%   (layout: docs/hdf5.md).
%
%   H = READ_HISTORY(FILE) returns a struct with
%     H.file          the file name
%     H.t, H.theta, H.theta_dot, H.k_left, H.k_right, H.ground_acc, H.w_excitation,
%     H.w_anchorage, H.e_switch
%                     every dataset of the file as an n x 1 column, n samples in time
%     H.units         the units attribute of each dataset (H.units.theta is 'rad')
%     H.attrs         root attributes: outcome, impacts, t_overturn, max_rotation, the
%                     settings of the run (anchorage, omega_ratio, config, ...)
%
%   Example:
%     H = read_history('history.h5');
%     plot(H.t, H.theta / H.attrs.alpha_rad); xlabel('t [s]'); ylabel('\theta / \alpha')
%
%   Runs in MATLAB (R2012a or later) and in GNU Octave with the netcdf package
%   (Debian: octave-netcdf; loaded here when needed), like read_spectra.

    load_netcdf();
    info = ncinfo(file);
    H = struct();
    H.file = file;
    H.units = struct();
    H.attrs = nc_attributes(info.Attributes);
    for v = 1:numel(info.Variables)
        var = info.Variables(v);
        x = ncread(file, ['/' var.Name]);
        H.(var.Name) = x(:);
        a = nc_attributes(var.Attributes);
        if isfield(a, 'units')
            H.units.(var.Name) = a.units;
        end
    end
end
