## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{v} =} repro_row (@var{R}, @var{field}, @var{nk})
## The values of @var{field} in a step record's struct array @var{R} (one
## per lobe count, as repro_render_fits and repro_judge write them) as a
## 1 x @var{nk} row, for both reports; NaN for what the record lacks or
## holds as null (NaN, Inf).
## @end deftypefn
function v = repro_row (R, field, nk)
  v = nan (1, nk);
  if (! isfield (R, field))
    return;
  endif
  for j = 1:min (nk, numel (R))
    x = R(j).(field);
    if (isnumeric (x) && isscalar (x))
      v(j) = x;
    endif
  endfor
endfunction
