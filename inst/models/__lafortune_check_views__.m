## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{own} =} __lafortune_check_views__ (@var{wo}, @var{wi}, @var{own}, @var{fname})
## The one check of the directions of @code{brdf_sample} and
## @code{brdf_pdf} (internal): @var{wo} M x 3 and @var{wi} N x 3 real and
## finite, @var{own} N indices into the rows of @var{wo} (empty: wo has N
## rows, each its own), else error @code{lafortune:badDirections}.
## Returns @var{own} as a column.
## @end deftypefn
function own = __lafortune_check_views__ (wo, wi, own, fname)
  ok = (isnumeric (wo) && isnumeric (wi) && isreal (wo) && isreal (wi) && columns (wo) == 3
        && columns (wi) == 3 && all (isfinite (wo(:))) && all (isfinite (wi(:))));
  if (ok && isempty (own))
    ok = rows (wo) == rows (wi);
    own = (1:rows (wo)).';
  elseif (ok)
    own = own(:);
    ok = (isnumeric (own) && numel (own) == rows (wi) && all (own == fix (own))
          && all (own >= 1 & own <= rows (wo)));
  endif
  if (! ok)
    error ("lafortune:badDirections",
           "%s: WO (M x 3) and WI (N x 3) must be real and finite, with N = M or OWN N indices into WO's rows, got %s and %s",
           fname, mat2str (size (wo)), mat2str (size (wi)));
  endif
  own = double (own);
endfunction
