function load_netcdf()
%LOAD_NETCDF  Makes ncinfo and ncread available: MATLAB has them built in, Octave keeps them
%   in its netcdf package (Debian: octave-netcdf).
    if exist('OCTAVE_VERSION', 'builtin') && ~exist('ncread', 'file')
        pkg('load', 'netcdf');
    end
end
