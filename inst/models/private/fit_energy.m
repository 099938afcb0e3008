## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn  {} {[@var{u}, @var{enforced}] =} fit_energy (@var{D}, @var{u})
## @deftypefnx {} {@var{theta} =} fit_energy ()
## brdf_fit's option "energy" (private): when the physically based model of
## the fit coordinates @var{u} (fit_phys, data @var{D} scaled by
## @code{D.sc}) reflects more than it receives (albedo > 1 in data units at
## any of the incidence angles 0, 5, ..., 85, 89 degrees, model_albedo;
## without arguments, those angles in degrees),
## it is refitted by Octave's @code{sqp} with the constraint albedo <= 1 at
## those angles and the fit's bounds, from the fit scaled down until it
## conserves energy (the albedo is linear in rho_d and ks).  leasqr takes
## bounds only.  @var{enforced} says whether the refit ran.
## @end deftypefn

function [u, enforced] = fit_energy (D, u)
  TH = [0:5:85, 89]' * pi / 180;
  if (nargin == 0)
    u = TH * 180 / pi;                    # the angles, for the fit's report
    return;
  endif
  A = albedo_of (D, u, TH);
  enforced = false;
  if (all (A(:) <= 1))
    return;
  endif
  enforced = true;
  def = D.def;
  ns = numel (def.shape);
  P = fit_phys ("split", D, u);
  amp = [1, 2 + (0:(rows (P) - 1) / (1 + ns) - 1) * (1 + ns)];
  for c = 1:D.nch
    f = max (A(c,:));
    if (f > 1)
      P(amp,c) /= f * (1 + 1e-9);
    endif
  endfor
  u0 = fit_phys ("join", D, P);
  [lb, ub] = fit_phys ("bounds", D, numel (u));
  u0 = min (max (u0, lb), ub);
  ss0 = max (sumsq_of (D, u0), realmin);
  phi = @(x) sumsq_of (D, x) / ss0;
  grad = @(x) grad_of (D, x) / ss0;
  h = @(x) 1 - reshape (albedo_of (D, x, TH), [], 1);
  x = u0;
  try
    [x, ~, st] = sqp (u0, {phi, grad}, [], h, lb, ub, 200, 1e-10);
  catch
    st = -1;
  end_try_catch
  x = min (max (x, lb), ub);             # sqp may step a rounding outside
  if (all (isfinite (x)) && all (h (x) >= -1e-9) && phi (x) <= 1)
    u = x;
  else
    u = u0;
  endif
  ## sqp meets the constraint to its tolerance: an albedo a hair above 1 is
  ## scaled to just below it, so that the fit's report (albedo <= 1) holds
  A = albedo_of (D, u, TH);
  P = fit_phys ("split", D, u);
  for c = 1:D.nch
    f = max (A(c,:));
    if (f > 1 - 1e-12)
      P(amp,c) /= f / (1 - 1e-12);
    endif
  endfor
  u = fit_phys ("join", D, P);
endfunction

## nch x numel (TH) albedos in data units
function A = albedo_of (D, u, TH)
  P = fit_phys ("split", D, u);
  A = zeros (D.nch, numel (TH));
  for c = 1:D.nch
    A(c,:) = D.sc(c) * model_albedo (D.def, P(:,c), TH).';
  endfor
endfunction

function ss = sumsq_of (D, u)
  f = fit_eval (D, u);
  if (! D.identity)
    f = D.t (f, D.c);
  endif
  ss = sum (D.w .^ 2 .* (D.ty - f) .^ 2);
endfunction

function g = grad_of (D, u)
  [f, J] = fit_eval (D, u);
  t = f;
  if (! D.identity)
    t = D.t (f, D.c);
    J .*= D.dt (f, D.c);
  endif
  g = -2 * J.' * (D.w .^ 2 .* (D.ty - t));
endfunction
