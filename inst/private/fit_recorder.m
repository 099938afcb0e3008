## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{rec} =} fit_recorder (@var{t0}, @var{tol})
## The state of one Levenberg-Marquardt run (private).  leasqr calls the
## model function and its Jacobian and nothing else, so the run (fit_lm)
## hands this handle to both, as fminsearch's OutputFcn gets the caller's
## own store; the run returns what it noted as outputs.
##
## @code{rec.add (obj, rmse)} notes a row [elapsed_s, obj, rmse] of
## @code{rec.T} (the trace; @var{t0} is a @code{tic} value, elapsed times
## are measured from it).
##
## @code{rec.flat (p, w, J, r)}, at the start of each iteration (leasqr asks
## for the Jacobian once per iteration, at its best point @var{p}; @var{w}
## the weights, @var{J} the Jacobian, @var{r} the residual there): true when
## the sum of squares ss = sumsq (w .* r) can no longer fall by @var{tol}
## times itself.
## That is MINPACK's test: the decrease that the Gauss-Newton step predicts
## (leasqr's least damping, 1e-7 on the normalised squared singular values,
## included) is below @var{tol} * ss.  It is computed only when the last
## iteration's decrease was below 100 @var{tol} * ss (with linear
## convergence the next one is smaller still), so most iterations cost
## one sum of squares.  @code{rec.p} is then the point and @code{rec.iter}
## the iterations done.  leasqr's own test needs one more iteration whose
## decrease falls short, and that iteration tries five dampings, one
## evaluation each, before it gives up.
## @end deftypefn
classdef fit_recorder < handle
  properties
    t0 = [];
    tol = 0;
    T = zeros (0, 3);
    p = [];
    iter = -1;
    ss = Inf;
  endproperties
  methods
    function obj = fit_recorder (t0, tol)
      obj.t0 = t0;
      obj.tol = tol;
    endfunction
    function add (obj, o, e)
      obj.T(end+1,:) = [toc(obj.t0), o, e];
    endfunction
    function tf = flat (obj, p, w, J, r)
      r .*= w;
      ss = r' * r;
      last = obj.ss - ss;
      obj.ss = ss;
      obj.p = p;
      obj.iter += 1;
      tf = last < 100 * obj.tol * ss && predicted_decrease (w .* J, r) < obj.tol * ss;
    endfunction
  endmethods
endclassdef

## The decrease of r'*r that the Gauss-Newton step predicts, with Jw's
## columns normalised and their squared singular values (eigenvalues of the
## normal matrix) at least 1e-7, leasqr's least damping
function d = predicted_decrease (Jw, r)
  A = Jw' * Jw;
  g = Jw' * r;
  s = sqrt (diag (A));
  s(! (s > 0)) = 1;
  A = A ./ (s * s');
  g ./= s;
  [V, L] = eig ((A + A') / 2);
  d = sum ((V' * g) .^ 2 ./ max (diag (L), 1e-7));
endfunction
