## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{T} =} fit_trace (@var{cmd}, @dots{})
## Record of objective values against elapsed time during a fit (private).
## fit_trace ("start") resets the clock; fit_trace ("add", obj, err) appends
## a row [elapsed_s, obj, err]; T = fit_trace ("get") returns the rows.
## @end deftypefn
function T = fit_trace (cmd, obj, err)
  persistent t0 rows_ n;
  T = [];
  switch (cmd)
    case "start"
      t0 = tic ();
      rows_ = zeros (256, 3);
      n = 0;
    case "add"
      n += 1;
      if (n > rows (rows_))
        rows_(2 * n, 3) = 0;
      endif
      rows_(n,:) = [toc(t0), obj, err];
    case "get"
      T = rows_(1:n,:);
  endswitch
endfunction
