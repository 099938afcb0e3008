## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} __lafortune_check_merl__ (@var{brdf}, @var{fname})
## Validate a MERL material struct (private): fields @code{data}
## (1458000 x 3 real) and @code{valid} (1458000 x 1 logical).  Error id
## @code{lafortune:badMerl}.
## @end deftypefn
function __lafortune_check_merl__ (brdf, fname)
  [~, ~, n] = __lafortune_merl_consts__ ();
  if (! isstruct (brdf) || ! isscalar (brdf) || ! isfield (brdf, "data")
      || ! isfield (brdf, "valid"))
    error ("lafortune:badMerl",
           "%s: BRDF must be a MERL material struct (fields data, valid) from merl_read or merl_synth",
           fname);
  endif
  if (! isequal (size (brdf.data), [n 3]) || ! isnumeric (brdf.data))
    error ("lafortune:badMerl", "%s: BRDF.data must be %d x 3 numeric, got %s",
           fname, n, mat2str (size (brdf.data)));
  endif
  if (! isequal (size (brdf.valid), [n 1]) || ! islogical (brdf.valid))
    error ("lafortune:badMerl", "%s: BRDF.valid must be %d x 1 logical", fname, n);
  endif
endfunction
