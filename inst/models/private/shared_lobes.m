## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {[@var{f}, @var{J}] =} shared_lobes ("eval", @var{p}, @var{ref}, @var{nch}, @var{sxy}, @var{sz})
## @deftypefnx {} {@var{P} =} shared_lobes ("split", @var{p}, @var{ref}, @var{nch})
## @deftypefnx {} {@var{p} =} shared_lobes ("join", @var{P}, @var{ref})
## @deftypefnx {} {[@var{lb}, @var{ub}] =} shared_lobes ("bounds", @var{np}, @var{nch})
## @deftypefnx {} {@var{p} =} shared_lobes ("unscale", @var{p}, @var{s}, @var{ref}, @var{nch})
## The parameters of Lafortune lobes shared across @var{nch} colour
## channels (private; lafortune_fit's @qcode{"color", "shared"}).
##
## Each lobe has one direction (Cxy, Cz) and one exponent e for every
## channel and an amplitude per channel: channel c's lobe is
## t_c max (Cxy sxy + Cz sz, 0)^e, with t_ref = 1 for the reference channel
## @var{ref} (an index in 1..@var{nch}: its lobe is the ordinary Lafortune
## lobe, whose size is |C|^e) and t_c >= 0 for the others.  One amplitude is
## fixed because the size of (Cxy, Cz) is an amplitude already: six
## parameters per lobe would leave a direction in which the model does not
## change, and leasqr's steps along it are noise.  @var{p} is
## [rho_1; ...; rho_nch; then per lobe Cxy; Cz; e; t of the other channels
## in order], 5 + ... parameters per lobe for three channels.
##
## @code{"eval"}: the model's values at the pairs (sxy, sz), channel after
## channel (nch G x 1), and the Jacobian; each lobe's power and derivatives
## come from lafortune_core, the one evaluation of the model.
## @code{"split"}: the @var{nch} per-channel parameter vectors of
## lafortune_core (a cell; columns), channel c's lobe folded into its
## direction: C_c = t_c^(1/e) (Cxy, Cz), which is exact (t_c C^e =
## (t_c^(1/e) C)^e); a lobe with e = 0 is a step and keeps (Cxy, Cz).
## @code{"join"}: the inverse of split for per-channel vectors whose lobes
## share directions and exponents (a start given as a model): exponent and
## direction from the reference channel, t_c = (|C_c| / |C_ref|)^e.
## @code{"bounds"}: rho >= 0, 0 <= e <= 1e7, t >= 0.  @code{"unscale"}: the
## parameters of the data divided by @var{s} (one scale for all channels)
## mapped back to the data's units (rho times s, the reference lobe's
## direction times s^(1/e), as brdf_lafortune's coordinates do for one channel).
## @end deftypefn
function varargout = shared_lobes (what, varargin)
  switch (what)
    case "eval"
      [varargout{1:max (nargout, 1)}] = shared_eval (varargin{:});
    case "split"
      varargout{1} = split (varargin{:});
    case "join"
      varargout{1} = join (varargin{:});
    case "bounds"
      [varargout{1:2}] = bounds (varargin{:});
    case "unscale"
      varargout{1} = unscale (varargin{:});
    otherwise
      error ("shared_lobes: unknown request %s", what);
  endswitch
endfunction

function [f, J] = shared_eval (p, ref, nch, sxy, sz)
  G = numel (sxy);
  per = 3 + nch - 1;
  nl = (numel (p) - nch) / per;
  oth = others (ref, nch);
  f = repmat (p(1:nch).' / pi, G, 1);
  jac = nargout > 1;
  if (jac)
    J = zeros (G * nch, numel (p));
    for c = 1:nch
      J((c-1)*G+1:c*G, c) = 1 / pi;
    endfor
  endif
  for k = 1:nl
    i0 = nch + (k - 1) * per;
    q = [0; p(i0+1:i0+3)];
    if (jac)
      [L, JL] = __lafortune_lafortune_core__ (q, sxy, sz);
    else
      L = __lafortune_lafortune_core__ (q, sxy, sz);
    endif
    t = ones (1, nch);
    t(oth) = p(i0+4:i0+per);
    f += L .* t;
    if (jac)
      for c = 1:nch
        r = (c-1)*G+1:c*G;
        J(r,i0+1:i0+3) = t(c) * JL(:,2:4);
      endfor
      for i = 1:numel (oth)
        c = oth(i);
        J((c-1)*G+1:c*G, i0+3+i) = L;
      endfor
    endif
  endfor
  f = f(:);
endfunction

function P = split (p, ref, nch)
  per = 3 + nch - 1;
  nl = (numel (p) - nch) / per;
  oth = others (ref, nch);
  P = cell (1, nch);
  for c = 1:nch
    P{c} = zeros (1 + 3 * nl, 1);
    P{c}(1) = p(c);
  endfor
  for k = 1:nl
    i0 = nch + (k - 1) * per;
    C = p(i0+1:i0+2);
    e = p(i0+3);
    t = ones (1, nch);
    t(oth) = p(i0+4:i0+per);
    for c = 1:nch
      g = 1;
      if (e > 0)
        g = exp (log (max (t(c), 0)) / e);     # t^(1/e); 0 for t = 0
      endif
      if (! isfinite (g))
        g = realmax;
      endif
      P{c}(3*k-1:3*k+1) = [g * C; e];
    endfor
  endfor
endfunction

function p = join (P, ref)
  nch = numel (P);
  nl = (numel (P{1}) - 1) / 3;
  oth = others (ref, nch);
  per = 3 + nch - 1;
  p = zeros (nch + nl * per, 1);
  for c = 1:nch
    p(c) = P{c}(1);
  endfor
  for k = 1:nl
    i0 = nch + (k - 1) * per;
    C = P{ref}(3*k-1:3*k);
    e = P{ref}(3*k+1);
    p(i0+1:i0+3) = [C; e];
    nr = norm (C);
    for i = 1:numel (oth)
      nc = norm (P{oth(i)}(3*k-1:3*k));
      t = 0;
      if (nr > 0 && nc > 0)
        t = exp (min (e * (log (nc) - log (nr)), 700));
      endif
      p(i0+3+i) = t;
    endfor
  endfor
endfunction

function [lb, ub] = bounds (np, nch)
  per = 3 + nch - 1;
  lb = -Inf (np, 1);
  ub = Inf (np, 1);
  lb(1:nch) = 0;
  for i0 = nch:per:np-per
    lb(i0+3) = 0; ub(i0+3) = 1e7;
    lb(i0+4:i0+per) = 0;
  endfor
endfunction

function p = unscale (p, s, ref, nch)
  if (s == 1)
    return;
  endif
  per = 3 + nch - 1;
  p(1:nch) *= s;
  for i0 = nch:per:numel(p)-per
    e = p(i0+3);
    f = exp (log (s) / e);
    if (e > 0 && isfinite (f) && f > 0)
      p(i0+1:i0+2) *= f;
    endif
  endfor
endfunction

function o = others (ref, nch)
  o = [1:ref-1, ref+1:nch];
endfunction
