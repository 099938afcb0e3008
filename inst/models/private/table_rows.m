## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## The rows K of the per-sample fields of the table S
function S = table_rows (S, k)
  if (all (k))
    return;
  endif
  n = numel (k);
  for f = {"wi", "wo", "rgb", "weight", "irradiance"}
    if (isfield (S, f{1}) && rows (S.(f{1})) == n)
      S.(f{1}) = S.(f{1})(k,:);
    endif
  endfor
endfunction
