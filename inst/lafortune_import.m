## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{model} =} lafortune_import (@var{file})
## Read a Lafortune model written by @code{lafortune_export} in the
## @code{"json"} format.
##
## The result has fields @code{name}, @code{rho_d} (1 x 3), @code{Cxy},
## @code{Cz} and @code{e} (nlobes x 3).  When the file holds the exact hex
## copies of the values, they are used (bit-for-bit round trip) after a
## check that they agree with the readable numbers.
##
## @example
## @group
## m = lafortune_import ("gmp-2lobe.json");
## f = lafortune_eval (m, [0 0 1], [0 0 1])
## @end group
## @end example
## @seealso{lafortune_export, lafortune_eval}
## @end deftypefn
function model = lafortune_import (file)
  if (nargin != 1)
    print_usage ();
  endif
  if (! ischar (file))
    error ("lafortune:badFile", "lafortune_import: FILE must be a file name");
  endif
  if (isfolder (file))
    error ("lafortune:isDirectory", "lafortune_import: '%s' is a directory, expected a .json file", file);
  endif
  if (! exist (file, "file"))
    error ("lafortune:fileNotFound", "lafortune_import: no such file '%s'", file);
  endif
  try
    s = jsondecode (fileread (file));
  catch err
    error ("lafortune:badFormat", "lafortune_import: '%s' is not valid JSON: %s", file, err.message);
  end_try_catch
  if (! isstruct (s) || ! isfield (s, "format") || ! strcmp (s.format, "lafortune-model"))
    error ("lafortune:badFormat",
           "lafortune_import: '%s' is not a lafortune model (expected \"format\": \"lafortune-model\")",
           file);
  endif
  need = {"nlobes", "rho_d", "Cxy", "Cz", "e"};
  for k = 1:numel (need)
    if (! isfield (s, need{k}))
      error ("lafortune:badFormat", "lafortune_import: '%s' has no field '%s'", file, need{k});
    endif
  endfor
  n = s.nlobes;
  if (! isnumeric (n) || ! isscalar (n) || n != fix (n) || n < 0 || n > 8)
    error ("lafortune:badFormat", "lafortune_import: '%s': nlobes must be an integer 0..8", file);
  endif
  model.name = "";
  if (isfield (s, "name") && ischar (s.name))
    model.name = s.name;
  endif
  model.rho_d = as_mat (s.rho_d, 1, "rho_d", file);
  for f = {"Cxy", "Cz", "e"}
    model.(f{1}) = as_mat (s.(f{1}), n, f{1}, file);
  endfor
  if (isfield (s, "exact"))
    ex = s.exact;
    for f = {"rho_d", "Cxy", "Cz", "e"}
      if (isfield (ex, f{1}))
        v = hex2num (char (ex.(f{1})));
        r = rows (model.(f{1}));
        if (numel (v) != 3 * r)
          error ("lafortune:badFormat", "lafortune_import: '%s': exact.%s has %d values, expected %d",
                 file, f{1}, numel (v), 3 * r);
        endif
        v = reshape (v, 3, r)';
        if (any (abs (v(:) - model.(f{1})(:)) > 1e-12 * max (1, abs (v(:)))))
          error ("lafortune:badFormat",
                 "lafortune_import: '%s': exact.%s disagrees with %s (edited by hand?)",
                 file, f{1}, f{1});
        endif
        model.(f{1}) = v;
      endif
    endfor
  endif
  nm = model.name;
  model = check_model (model, "lafortune_import");
  model.name = nm;
endfunction

function v = as_mat (v, r, name, file)
  if (! isnumeric (v) || numel (v) != 3 * r)
    error ("lafortune:badFormat", "lafortune_import: '%s': %s must hold %d x 3 numbers", file, name, r);
  endif
  if (r == 1 || isvector (v))
    v = reshape (v, 3, r)';
  endif
  v = double (v);
endfunction

%!shared d
%! d = tempname (); mkdir (d);

%!test
%! m = struct ("name", "one", "rho_d", [0.1 0.2 0.3], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [10 20 30]);
%! f = fullfile (d, "one.json");
%! lafortune_export (m, f, "json");
%! r = lafortune_import (f);
%! assert (r, m);
%! ## without the exact copies the readable numbers are used
%! s = jsondecode (fileread (f));
%! s = rmfield (s, "exact");
%! fid = fopen (f, "w"); fputs (fid, jsonencode (s)); fclose (fid);
%! r = lafortune_import (f);
%! assert (r.e, m.e, 1e-12);

%!error <Invalid call> lafortune_import ()
%!error id=lafortune:fileNotFound lafortune_import (fullfile (d, "none.json"))
%!error id=lafortune:isDirectory lafortune_import (d)
%!error <not valid JSON> fid = fopen (fullfile (d, "bad.json"), "w"); fputs (fid, "{oops"); fclose (fid); lafortune_import (fullfile (d, "bad.json"))
%!error <not a lafortune model> fid = fopen (fullfile (d, "o.json"), "w"); fputs (fid, "{\"a\": 1}"); fclose (fid); lafortune_import (fullfile (d, "o.json"))
%!error <Cxy must hold 2 x 3> fid = fopen (fullfile (d, "c.json"), "w"); fputs (fid, "{\"format\": \"lafortune-model\", \"nlobes\": 2, \"rho_d\": [0,0,0], \"Cxy\": [1,2,3], \"Cz\": [[1,2,3],[1,2,3]], \"e\": [[1,2,3],[1,2,3]]}"); fclose (fid); lafortune_import (fullfile (d, "c.json"))

%!test
%! assert (strncmp (d, tempdir (), numel (tempdir ())));   # only our scratch folder
%! confirm_recursive_rmdir (false, "local");
%! rmdir (d, "s");
