## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{f}, @var{J}] =} __lafortune_lafortune_core__ (@var{p}, @var{sxy}, @var{sz})
## The one evaluation of the isotropic Lafortune model for one channel (private).
##
## @var{p} = [rho_d; Cxy_1; Cz_1; e_1; Cxy_2; ...] (column), @var{sxy} =
## ux vx + uy vy and @var{sz} = uz vz (column vectors).  Returns
## f = rho_d/pi + sum_k max (Cxy_k sxy + Cz_k sz, 0)^e_k and, on request, the
## Jacobian df/dp (N x numel(p)).  Lobe bases are clamped at 0 and powers are
## taken in log space with the exponent of each lobe capped at LOGMAX = 300
## (a lobe never exceeds exp(300)), so the result is real and finite for any
## finite input.  lafortune_eval, lafortune_fit, the exports and both
## renderers go through this function.
##
## The arithmetic below is the reference.  When the oct-file
## @code{__lafortune_core__} (@file{src/}, built by @code{pkg install}) is on
## the path, it does the same operations in the same order, compiled, and
## this function calls it: the results are the same bit for bit
## (test/test_core_engines.m compares both, values, Jacobians and whole fits);
## it is faster (make bench's bench_fit, "Model engines", says by how
## much).  An oct-file that does not load (built for another
## Octave) raises the warning @code{lafortune:noOctFile} once and the
## Octave arithmetic is used.  Inputs are real doubles, @var{sxy} and
## @var{sz} columns (every caller's are).
## @end deftypefn
function [f, J] = __lafortune_lafortune_core__ (p, sxy, sz)
  persistent broken = false;
  if (! broken && exist ("__lafortune_core__", "file") == 3)
    try
      if (nargout > 1)
        [f, J] = __lafortune_core__ (p, sxy, sz);
      else
        f = __lafortune_core__ (p, sxy, sz);
      endif
      return;
    catch err
      ## its own errors (lafortune:badInput, lafortune:outOfMemory) stand;
      ## an oct-file that does not load (built for another Octave, damaged)
      ## is left for the rest of the session
      if (strncmp (err.identifier, "lafortune:", 10))
        rethrow (err);
      endif
      broken = true;
      warning ("lafortune:noOctFile",
               "lafortune_core: the oct-file __lafortune_core__ does not work (%s); using the Octave arithmetic (rebuild it: make -C src)",
               err.message);
    end_try_catch
  endif
  LOGMAX = 300;
  n = numel (sxy);
  nl = (numel (p) - 1) / 3;
  f = zeros (n, 1) + p(1) / pi;
  jac = nargout > 1;
  if (jac)
    J = zeros (n, numel (p));
    J(:,1) = 1 / pi;
  endif
  for k = 1:nl
    cxy = p(3*k-1);
    cz = p(3*k);
    e = p(3*k+1);
    ## a lobe is 0 where its base is not positive: only the samples ON it
    ## are computed (about half, for the fitted lobes)
    b = cxy * sxy + cz * sz;
    on = find (b > 0);
    if (isempty (on))
      continue;
    endif
    ## log of the base; realmin keeps it finite
    lb = log (max (b(on), realmin));
    if (e == 0)
      f(on) += 1;
      if (jac)
        J(on,3*k+1) = lb;
      endif
      continue;
    endif
    t = e * lb;
    L = exp (max (min (t, LOGMAX), -700));   # no denormals: they are slow
    f(on) += L;
    if (jac)
      ## d/db of b^e = e b^(e-1), formed in log space; 0 where capped (set,
      ## not multiplied by 0: e exp (300) overflows for e > 1e177)
      live = t <= LOGMAX;
      dLdb = e * exp (max (min (t - lb, LOGMAX), -700));
      dLdb(! live) = 0;
      J(on,3*k-1) = dLdb .* sxy(on);
      J(on,3*k)   = dLdb .* sz(on);
      J(on,3*k+1) = L .* lb .* live;
    endif
  endfor
endfunction
