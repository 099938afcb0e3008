## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{rec} =} fit_recorder (@var{t0})
## Rows [elapsed_s, objective, rmse] noted by one Levenberg-Marquardt run
## (private).  leasqr calls the model function and nothing else, so the run
## (fit_lm) hands this handle to its model function, as fminsearch's OutputFcn
## gets the caller's own store; the run returns the rows (@code{rec.T}) as an
## output, and the caller keeps them or not.  @var{t0} is a @code{tic} value:
## elapsed times are measured from it.
## @end deftypefn
classdef fit_recorder < handle
  properties
    t0 = [];
    T = zeros (0, 3);
  endproperties
  methods
    function obj = fit_recorder (t0)
      obj.t0 = t0;
    endfunction
    function add (obj, o, e)
      obj.T(end+1,:) = [toc(obj.t0), o, e];
    endfunction
  endmethods
endclassdef
