## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} pkg_load_optim ()
## Make the optim package's leasqr available (private), without the
## statistics package's "shadows a core library function" warnings.
## Error @code{lafortune:noOptim} when optim is not installed.
## @end deftypefn
function pkg_load_optim ()
  if (exist ("leasqr") >= 2)
    return;
  endif
  warning ("off", "Octave:shadowed-function");
  try
    pkg ("load", "optim");
  catch err
    error ("lafortune:noOptim",
           "lafortune: the optim package (leasqr) is needed: install Debian's octave-optim (%s)",
           err.message);
  end_try_catch
endfunction
