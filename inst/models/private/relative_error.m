## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {@var{r} =} relative_error (@var{e}, @var{e0})
## The relative error, the one definition (private): the error @var{e} of a
## model over the error @var{e0} of the model that is 0 everywhere (for the
## plain metric, the rms of the data), per channel; 0 where @var{e} is 0.
## @code{rel_rmse} of @code{lafortune_fit}, @code{brdf_fit} and
## @code{brdf_error}'s @code{info.relative}.
## @end deftypefn
function r = relative_error (e, e0)
  r = e ./ max (e0, realmin) .* (e > 0);
endfunction

%!assert (relative_error ([0 1 2], [1 2 0]), [0 0.5 2 / realmin])
%!assert (relative_error (0, 0), 0)
