## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{rec} =} fit_recorder (@var{t0}, @var{tol})
## The state of one Levenberg-Marquardt run (private).  leasqr calls the
## model function and its Jacobian and nothing else, so the run (fit_lm)
## hands this handle to both, as fminsearch's OutputFcn gets the caller's
## own store; the run returns what it noted as outputs.
##
## @code{rec.add (obj, rmse)} notes a row [elapsed_s, obj, rmse] (rmse one
## value per channel) of
## @code{rec.T} (the trace; @var{t0} is a @code{tic} value, elapsed times
## are measured from it).
##
## @code{rec.flat (p, w, J, r)}, at the start of each iteration (leasqr asks
## for the Jacobian once per iteration, at its best point @var{p}; @var{w}
## the weights, @var{J} the Jacobian, @var{r} the residual there): true when
## the sum of squares ss = sumsq (w .* r) can no longer fall by @var{tol}
## times itself: the decrease that the Gauss-Newton step predicts (MINPACK's
## predicted reduction) is below @var{tol} * ss / 2.  The half is a margin:
## in these large-residual fits a step can gain more than it predicts (the
## README's "Measurements behind the design" gives the measurement).  The prediction is computed only when
## the last iteration's decrease was below 100 @var{tol} * ss (with linear
## convergence the next one is smaller still), so most iterations cost one
## sum of squares.  @code{rec.p} is then the point and @code{rec.iter} the
## iterations done.  leasqr's own test needs one more iteration whose
## decrease falls short, and that iteration tries five dampings, one
## evaluation each, before it gives up.
##
## @code{rec.rerun ()} starts the test afresh (the constructor does too),
## for another run; the rows stay.
## @end deftypefn
classdef fit_recorder < handle
  properties
    t0 = [];
    tol = 0;
    T = [];
    p = [];
    iter = [];
    ss = [];
  endproperties
  methods
    function obj = fit_recorder (t0, tol)
      obj.t0 = t0;
      obj.tol = tol;
      obj.rerun ();
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
      tf = last < 100 * obj.tol * ss && predicted_decrease (w .* J, r) < obj.tol * ss / 2;
    endfunction
    function rerun (obj)
      obj.p = [];
      obj.iter = -1;
      obj.ss = Inf;
    endfunction
  endmethods
endclassdef

## The decrease of r'*r that the Gauss-Newton step predicts: the squared
## norm of r's projection on the columns of Jw, from the normal matrix with
## its columns normalised.  A direction of (nearly) zero eigenvalue makes
## it huge, so the run goes on: leasqr's own test then ends it
function d = predicted_decrease (Jw, r)
  A = Jw' * Jw;
  g = Jw' * r;
  s = sqrt (diag (A));
  s(! (s > 0)) = 1;
  A = A ./ (s * s');
  g ./= s;
  [V, L] = eig ((A + A') / 2);
  d = sum ((V' * g) .^ 2 ./ max (diag (L), realmin));
endfunction
