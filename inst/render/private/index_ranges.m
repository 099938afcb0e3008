## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{idx} =} index_ranges (@var{a}, @var{e})
## The indices @var{a}(1):@var{e}(1), @var{a}(2):@var{e}(2), @dots{} in one
## row (private, for the mesh readers), built without a loop.  Every range
## must be non-empty (@var{a}(k) <= @var{e}(k)).
## @end deftypefn
function idx = index_ranges (a, e)
  if (isempty (a))
    idx = zeros (1, 0);
    return;
  endif
  a = a(:).';
  e = e(:).';
  len = e - a + 1;
  idx = ones (1, sum (len));
  cs = cumsum (len);
  idx(1) = a(1);
  idx(cs(1:end-1) + 1) = a(2:end) - e(1:end-1);
  idx = cumsum (idx);
endfunction
