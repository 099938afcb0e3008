## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{wi}, @var{wo}] =} __lafortune_check_dirs__ (@var{wi}, @var{wo}, @var{fname})
## Validate two N x 3 arrays of unit directions (private).  A 1 x 3 array is
## expanded to the other's row count.  Errors: @code{lafortune:badDirections},
## @code{lafortune:notUnit}.
## @end deftypefn
function [wi, wo] = __lafortune_check_dirs__ (wi, wo, fname)
  names = {"WI", "WO"};
  args = {wi, wo};
  for k = 1:2
    a = args{k};
    if (! (isnumeric (a) && isreal (a)) || ndims (a) != 2 || columns (a) != 3)
      error ("lafortune:badDirections",
             "%s: %s must be a real N x 3 numeric array of unit directions, got %s %s",
             fname, names{k}, class (a), mat2str (size (a)));
    endif
    if (! isa (a, "double"))
      a = double (a);
    endif
    n2 = a(:,1) .* a(:,1) + a(:,2) .* a(:,2) + a(:,3) .* a(:,3);
    tol = 1e-6;
    if (isa (args{k}, "single"))
      tol = 1e-5;
    endif
    ## |n2 - 1| <= 2 tol covers |n - 1| <= tol; NaN and Inf fail it too
    bad = ! (abs (n2 - 1) <= 2 * tol);
    if (any (bad))
      if (! all (isfinite (a(:))))
        error ("lafortune:badDirections",
               "%s: %s must be finite, found NaN or Inf", fname, names{k});
      endif
      i = find (bad, 1);
      error ("lafortune:notUnit",
             "%s: %s must hold unit vectors (|v| = 1 within %g), row %d has norm %g",
             fname, names{k}, tol, i, sqrt (n2(i)));
    endif
    args{k} = double (a);
  endfor
  wi = args{1};
  wo = args{2};
  ni = rows (wi);
  no = rows (wo);
  if (ni != no)
    if (ni == 1)
      wi = repmat (wi, no, 1);
    elseif (no == 1)
      wo = repmat (wo, ni, 1);
    else
      error ("lafortune:badDirections",
             "%s: WI and WO must have the same number of rows (or one row), got %d and %d",
             fname, ni, no);
    endif
  endif
endfunction
