## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{L}, @var{wt}, @var{own}] =} mis_samples (@var{env}, @var{k}, @var{seed}, @var{Ns}, @var{Vw})
## The light directions of the hits of pixel samples @var{k} under an
## environment light by multiple importance sampling (private, for
## @code{scene_trace}): @code{env.nl} samples of the map (@code{light_samples}) and @code{env.nb} of the BRDF density
## @code{env.S} (@code{brdf_sample} about the shading normal @var{Ns} and
## the view @var{Vw}, stratified by another salt of @code{r2_points}),
## combined by the balance heuristic (Veach 1997, ch. 9): every sample,
## of either kind, weighs the map's radiance over nl p_light + nb p_brdf,
## so the mean of wt f cos over a pixel sample's samples, summed, estimates
## the integral of the map's radiance times f cos.  The weights depend on
## the density, not on the material shaded: another material shaded on the
## same samples (the trace cache) is estimated without bias as well.
## @var{L} (unit, world), @var{wt} (n x 3) and @var{own} (the row of @var{k}
## each sample is for) have one row per sample.
## @end deftypefn
function [L, wt, own] = mis_samples (env, k, seed, Ns, Vw)
  m = numel (k);
  [~, wo, X, Y] = local_dirs (Ns, Vw, Vw);
  L = zeros (0, 3);
  own = zeros (0, 1);
  if (env.nl > 0)                      # the map's samples, as light_samples draws them
    [L, ~, own] = light_samples (struct ("type", "environment"), env.D, k, env.nl, seed);
  endif
  if (env.nb > 0)
    [u, v] = r2_points (k, env.nb, seed, 2891336453);
    ob = repmat (1:m, env.nb, 1)(:);
    wl = brdf_sample (env.S, wo, [u v], ob);
    L = [L; wl(:,1) .* X(ob,:) + wl(:,2) .* Y(ob,:) + wl(:,3) .* Ns(ob,:)];
    own = [own; ob];
  endif
  L ./= sqrt (sum (L .^ 2, 2));
  wl = [sum(L .* X(own,:), 2), sum(L .* Y(own,:), 2), sum(L .* Ns(own,:), 2)];
  pb = brdf_pdf (env.S, wo, wl, own);
  [pl, rad] = env_pdf (env.D, L);
  den = env.nl * pl + env.nb * pb;
  wt = rad ./ den;
  wt(! (den > 0) | ! isfinite (den), :) = 0;
endfunction

