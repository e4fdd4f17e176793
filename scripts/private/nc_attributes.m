function A = nc_attributes(list)
%NC_ATTRIBUTES  An ncinfo attribute list as a struct: text as char rows, vectors as columns.
%   Shared by read_spectra and read_history (a private function: visible to them only).
    A = struct();
    for k = 1:numel(list)
        v = list(k).Value;
        if ischar(v)
            v = reshape(v, 1, []);
            v = v(v ~= char(0));   % "" is stored as one byte of padding
        elseif isnumeric(v) && ~isscalar(v)
            v = v(:);
        end
        A.(matlab.lang.makeValidName(list(k).Name)) = v;
    end
end
