## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{T} =} fit_trace (@var{cmd}, @dots{})
## Record of objective values against elapsed time during a fit (private).
## fit_trace ("start") resets the clock and the record; fit_trace ("add",
## obj, err) appends a pending row [elapsed_s, obj, err]; fit_trace
## ("commit") keeps the pending rows, fit_trace ("drop") discards them (a
## result that was not accepted); T = fit_trace ("get") returns the kept rows.
## @end deftypefn
function T = fit_trace (cmd, obj, err)
  persistent t0 kept pend;
  T = [];
  switch (cmd)
    case "start"
      t0 = tic ();
      kept = zeros (0, 3);
      pend = zeros (0, 3);
    case "add"
      pend(end+1,:) = [toc(t0), obj, err];
    case "commit"
      kept = [kept; pend];
      pend = zeros (0, 3);
    case "drop"
      pend = zeros (0, 3);
    case "get"
      T = kept;
  endswitch
endfunction
