## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{T} =} repro_trace (@var{tr}, @var{ch})
## The error-against-time trace of channel @var{ch} (K x 2: seconds, rmse)
## from a fit record read back from JSON, where jsondecode gives a cell
## (traces of different lengths) or a 3-D array (equal lengths).
## @end deftypefn
function T = repro_trace (tr, ch)
  if (iscell (tr))
    T = tr{ch};
  else
    T = squeeze (tr(ch,:,:));
  endif
endfunction
