## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{model} =} brdf_import (@var{file})
## Read an analytic model written by @code{brdf_export} in the
## @code{"json"} format: a Lafortune model or any other type of
## @code{brdf_model}.
##
## A Lafortune file (@code{"format": "lafortune-model"}) gives a struct
## with fields @code{name}, @code{rho_d} (1 x 3), @code{Cxy}, @code{Cz} and
## @code{e} (nlobes x 3).  Another type's file (@code{"format":
## "brdf-model"}) gives a struct with fields @code{type}, @code{name},
## @code{rho_d} and, nlobes x 3 each, @code{ks} and the type's shape
## parameters (see @code{brdf_model (type)}).  @code{name} is "" when the
## file has none.  When the file holds the exact hex copies of the values,
## they are used (bit-for-bit round trip) after a check that they agree
## with the readable numbers.  The model is checked as every function
## checks one (its type's fields, sizes and bounds).
##
## Errors: @code{lafortune:badFile}, @code{lafortune:fileNotFound},
## @code{lafortune:isDirectory}, @code{lafortune:badFormat} (not JSON, not
## a model, a field missing or of the wrong size, exact copies that
## disagree), @code{lafortune:badModel} (values out of the type's bounds).
##
## @example
## @group
## m = brdf_import ("gmp-2lobe.json");
## f = material_eval (m, [0 0 1], [0 0 1])
## g = brdf_model ("ggx", "rho_d", [0.1 0.05 0.02], "ks", 1, ...
##                 "alpha", 0.2, "F0", 0.04, "name", "gloss");
## brdf_export (g, "gloss.json");
## isequal (brdf_import ("gloss.json"), g)    # true
## @end group
## @end example
## @seealso{brdf_export, brdf_model, material_eval, lafortune_eval}
## @end deftypefn
function model = brdf_import (file)
  if (nargin != 1)
    print_usage ();
  endif
  if (! ischar (file))
    error ("lafortune:badFile", "brdf_import: FILE must be a file name");
  endif
  if (isfolder (file))
    error ("lafortune:isDirectory", "brdf_import: '%s' is a directory, expected a .json file", file);
  endif
  if (! exist (file, "file"))
    error ("lafortune:fileNotFound", "brdf_import: no such file '%s'", file);
  endif
  try
    s = jsondecode (fileread (file));
  catch err
    error ("lafortune:badFormat", "brdf_import: '%s' is not valid JSON: %s", file, err.message);
  end_try_catch
  if (! isstruct (s) || ! isscalar (s) || ! isfield (s, "format") || ! ischar (s.format)
      || ! any (strcmp (s.format, {"lafortune-model", "brdf-model"})))
    error ("lafortune:badFormat",
           "brdf_import: '%s' is not a lafortune model (expected \"format\": \"lafortune-model\", or \"brdf-model\" with a \"type\")",
           file);
  endif
  type = "lafortune";
  if (strcmp (s.format, "brdf-model"))
    types = __lafortune_model_def__ ();
    if (! isfield (s, "type") || ! ischar (s.type) || ! any (strcmp (s.type, types)))
      error ("lafortune:badFormat", "brdf_import: '%s': \"type\" must be one of %s",
             file, strjoin (types, ", "));
    endif
    type = s.type;
  endif
  def = __lafortune_model_def__ (type);
  need = [{"nlobes"}, def.fields];
  for k = 1:numel (need)
    if (! isfield (s, need{k}))
      error ("lafortune:badFormat", "brdf_import: '%s' has no field '%s'", file, need{k});
    endif
  endfor
  n = s.nlobes;
  if (! isnumeric (n) || ! isscalar (n) || n != fix (n) || n < 0 || n > 8)
    error ("lafortune:badFormat", "brdf_import: '%s': nlobes must be an integer 0..8", file);
  endif
  model = struct ();
  if (! isempty (def.lobe))
    model.type = type;
  endif
  model.name = "";
  if (isfield (s, "name") && ischar (s.name))
    model.name = s.name;
  endif
  model.rho_d = as_mat (s.rho_d, 1, "rho_d", file);
  for f = def.fields(2:end)
    model.(f{1}) = as_mat (s.(f{1}), n, f{1}, file);
  endfor
  if (isfield (s, "exact"))
    ex = s.exact;
    if (! isstruct (ex) || ! isscalar (ex))
      error ("lafortune:badFormat", "brdf_import: '%s': exact must be an object", file);
    endif
    for f = def.fields
      if (isfield (ex, f{1}))
        v = hex_values (ex.(f{1}), f{1}, file);
        r = rows (model.(f{1}));
        if (numel (v) != 3 * r)
          error ("lafortune:badFormat", "brdf_import: '%s': exact.%s has %d values, expected %d",
                 file, f{1}, numel (v), 3 * r);
        endif
        v = reshape (v, 3, r)';
        if (any (abs (v(:) - model.(f{1})(:)) > 1e-12 * max (1, abs (v(:)))))
          error ("lafortune:badFormat",
                 "brdf_import: '%s': exact.%s disagrees with %s (edited by hand?)",
                 file, f{1}, f{1});
        endif
        model.(f{1}) = v;
      endif
    endfor
  endif
  nm = model.name;
  model = __lafortune_check_model__ (model, "brdf_import");
  __lafortune_check_bounded__ (model, sprintf ("brdf_import: '%s'", file));
  model.name = nm;
endfunction

function v = as_mat (v, r, name, file)
  if (! isnumeric (v) || numel (v) != 3 * r)
    error ("lafortune:badFormat", "brdf_import: '%s': %s must hold %d x 3 numbers", file, name, r);
  endif
  if (r == 1 || isvector (v))
    v = reshape (v, 3, r)';
  endif
  v = double (v);
endfunction

## the doubles of a list of IEEE-754 hex strings (16 hex digits each); none
## for an empty list or a list of empty strings (no lobes)
function v = hex_values (h, name, file)
  if (ischar (h))
    h = cellstr (h);
  endif
  if (isempty (h) || (iscellstr (h) && all (cellfun ("isempty", h))))
    v = zeros (0, 1);
    return;
  endif
  if (! iscellstr (h) || ! all (cellfun (@(x) numel (x) == 16 && all (isxdigit (x)), h)))
    error ("lafortune:badFormat",
           "brdf_import: '%s': exact.%s must be a list of 16-digit hex strings", file, name);
  endif
  v = hex2num (char (h(:)));
endfunction

%!shared d
%! d = tempname (); mkdir (d);

%!test
%! m = struct ("name", "one", "rho_d", [0.1 0.2 0.3], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [10 20 30]);
%! f = fullfile (d, "one.json");
%! brdf_export (m, f, "json");
%! r = brdf_import (f);
%! assert (r, m);
%! ## without the exact copies the readable numbers are used
%! s = jsondecode (fileread (f));
%! s = rmfield (s, "exact");
%! fid = fopen (f, "w"); fputs (fid, jsonencode (s)); fclose (fid);
%! r = brdf_import (f);
%! assert (r.e, m.e, 1e-12);

%!test
%! ## a file whose model is infinite somewhere on the hemisphere is refused
%! ## (written by another tool: here by hand)
%! m = struct ("name", "boom", "rho_d", [0.1 0.2 0.3], "Cxy", [-1.5 -1 -1], "Cz", [0.9 1 1],
%!             "e", [738 20 30]);
%! f = fullfile (d, "boom.json");
%! brdf_export (setfield (m, "e", [1 20 30]), f, "json");
%! s = jsondecode (fileread (f));
%! s = rmfield (s, "exact");
%! s.e = m.e;
%! fid = fopen (f, "w"); fputs (fid, jsonencode (s)); fclose (fid);
%! try
%!   brdf_import (f);
%!   error ("test:none", "no error");
%! catch err
%!   assert (err.identifier, "lafortune:unboundedModel");
%!   assert (! isempty (strfind (err.message, "boom.json': the model is unbounded: channel 1, lobe 1,")));
%!   assert (! isempty (strfind (err.message, "grazing light and view on the mirror side")));
%! end_try_catch

%!test
%! ## every type back bit for bit, with its type; a readable value alone
%! ## when the exact copies are gone
%! for t = brdf_model ()(2:end)
%!   def = brdf_model (t{1});
%!   m = brdf_model (t{1}, "rho_d", [0.1 0.2 pi/10], "ks", [1 2 3; 0.1 0.2 pi/7], ...
%!                   def.shape{1}, [0.3 0.4 0.5; 0.6 0.7 0.8] * (1 + 10 * (def.hi(2) > 100)) / 3, ...
%!                   "name", t{1});
%!   f = fullfile (d, [t{1} ".json"]);
%!   brdf_export (m, f, "json");
%!   r = brdf_import (f);
%!   assert (isequal (r, m));
%!   assert (r.type, t{1});
%!   assert (r.ks(2,3), pi / 7);
%!   s = jsondecode (fileread (f));
%!   s = rmfield (s, "exact");
%!   fid = fopen (f, "w"); fputs (fid, jsonencode (s)); fclose (fid);
%!   r = brdf_import (f);
%!   assert (r.(def.shape{1}), m.(def.shape{1}), 1e-15);
%! endfor

%!test
%! ## a model without lobes and one without a name
%! f = fullfile (d, "zero.json");
%! m = struct ("rho_d", [0.1 0.2 0.3], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! brdf_export (m, f, "json");
%! r = brdf_import (f);
%! assert (r.name, "lafortune-model");
%! assert (isequal (r.rho_d, m.rho_d) && isequal (size (r.Cxy), [0 3]));
%! assert (isempty (strfind (fileread (f), '[""]')));     # no lobes: an empty list, as every type
%! g = brdf_model ("ward", "rho_d", [0.1 0.2 0.3]);
%! brdf_export (g, f, "json");
%! r = brdf_import (f);
%! assert (r.name, "ward-model");
%! assert (isequal (rmfield (r, "name"), g));

%!error <Invalid call> brdf_import ()
%!error id=lafortune:fileNotFound brdf_import (fullfile (d, "none.json"))
%!error id=lafortune:isDirectory brdf_import (d)
%!error <not valid JSON> fid = fopen (fullfile (d, "bad.json"), "w"); fputs (fid, "{oops"); fclose (fid); brdf_import (fullfile (d, "bad.json"))
%!error <not a lafortune model> fid = fopen (fullfile (d, "o.json"), "w"); fputs (fid, "{\"a\": 1}"); fclose (fid); brdf_import (fullfile (d, "o.json"))
%!error <Cxy must hold 2 x 3> fid = fopen (fullfile (d, "c.json"), "w"); fputs (fid, "{\"format\": \"lafortune-model\", \"nlobes\": 2, \"rho_d\": [0,0,0], \"Cxy\": [1,2,3], \"Cz\": [[1,2,3],[1,2,3]], \"e\": [[1,2,3],[1,2,3]]}"); fclose (fid); brdf_import (fullfile (d, "c.json"))

%!function f = js (d, name, txt)
%!  ## a file NAME in D holding TXT
%!  f = fullfile (d, name);
%!  fid = fopen (f, "w");
%!  fputs (fid, txt);
%!  fclose (fid);
%!endfunction

%!error <"type" must be one of> brdf_import (js (d, "t.json", "{\"format\": \"brdf-model\", \"type\": \"phong\"}"))
%!error <"type" must be one of> brdf_import (js (d, "t.json", "{\"format\": \"brdf-model\"}"))
%!error <has no field 'F0'> brdf_import (js (d, "t.json", "{\"format\": \"brdf-model\", \"type\": \"ggx\", \"nlobes\": 1, \"rho_d\": [0,0,0], \"ks\": [1,1,1], \"alpha\": [1,1,1]}"))
%!error <alpha must hold 2 x 3> brdf_import (js (d, "t.json", "{\"format\": \"brdf-model\", \"type\": \"ggx\", \"nlobes\": 2, \"rho_d\": [0,0,0], \"ks\": [[1,1,1],[1,1,1]], \"alpha\": [1,1,1], \"F0\": [[0,0,0],[0,0,0]]}"))
%!error id=lafortune:badModel brdf_import (js (d, "t.json", "{\"format\": \"brdf-model\", \"type\": \"ggx\", \"nlobes\": 1, \"rho_d\": [0,0,0], \"ks\": [1,1,1], \"alpha\": [0,1,1], \"F0\": [0,0,0]}"))
%!error <exact.ks disagrees> brdf_import (js (d, "t.json", "{\"format\": \"brdf-model\", \"type\": \"ward\", \"nlobes\": 1, \"rho_d\": [0,0,0], \"ks\": [1,1,1], \"alpha\": [1,1,1], \"exact\": {\"ks\": [\"3ff0000000000000\", \"3ff0000000000000\", \"4000000000000000\"]}}"))
%!error <exact.ks must be a list of 16-digit hex> brdf_import (js (d, "t.json", "{\"format\": \"brdf-model\", \"type\": \"ward\", \"nlobes\": 1, \"rho_d\": [0,0,0], \"ks\": [1,1,1], \"alpha\": [1,1,1], \"exact\": {\"ks\": [\"3ff0\", \"3ff0000000000000\", \"3ff0000000000000\"]}}"))
%!error <not a lafortune model> brdf_import (js (d, "t.json", "[1, 2]"))

%!test
%! assert (strncmp (d, tempdir (), numel (tempdir ())));   # only our scratch folder
%! confirm_recursive_rmdir (false, "local");
%! rmdir (d, "s");
