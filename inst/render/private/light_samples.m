## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{L}, @var{wt}, @var{own}] =} light_samples (@var{light}, @var{D}, @var{k}, @var{ns}, @var{seed})
## The light directions of the hits of the pixel samples @var{k} (0-based,
## as @code{sample_rays}) under an environment light or a list of
## directional lights (private, for @code{scene_trace}).  An environment
## light (@var{D} from @code{env_dist}) gets @var{ns} samples per pixel
## sample: the first @var{ns} points of the R2 sequence (a rank-1 lattice of
## low discrepancy, so the @var{ns} samples of a pixel sample are
## stratified), shifted (modulo 1) by two uniforms hashed from @var{k} and
## @var{seed} (a Cranley-Patterson rotation, independent from one pixel
## sample to the next), mapped through @code{env_sample}; so the samples
## depend on @var{k} and @var{seed} only, not on how many are traced at once.
## A list of lights gives every hit each light.  @var{L} (unit, world),
## @var{wt} (the radiance over the density divided by @var{ns}, or each
## light's irradiance) and @var{own} (the row of @var{k} each sample is
## for) have one row per sample.
## @end deftypefn
function [L, wt, own] = light_samples (light, D, k, ns, seed)
  m = numel (k);
  if (strcmp (light.type, "lights"))
    K = rows (light.directions);
    own = repmat (1:m, K, 1)(:);
    Ld = light.directions ./ sqrt (sum (light.directions .^ 2, 2));
    E = double (light.irradiance) .* [1 1 1];
    L = repmat (Ld, m, 1);
    wt = repmat (E, m, 1);
    return;
  endif
  ## the ns points of the R2 sequence (1/phi2, 1/phi2^2), each pixel sample's
  ## own random shift of them (a hash of k and the seed: independent from
  ## sample to sample, so the image has noise, not the lattice's pattern)
  j = (0:ns-1).';
  a1 = 0.7548776662466927;
  a2 = 0.5698402909980532;
  x = mod (double (k(:)).' + double (seed) * 2654435769, 2 ^ 32);     # 1 x m
  h1 = hash32 (x);
  h2 = hash32 (mod (h1 + 1013904223, 2 ^ 32));
  u = mod (0.5 + j * a1 + (h1 + 0.5) / 2 ^ 32, 1);                  # ns x m
  v = mod (0.5 + j * a2 + (h2 + 0.5) / 2 ^ 32, 1);
  u = u(:);
  v = v(:);
  own = repmat (1:m, ns, 1)(:);
  [L, wt] = env_sample (D, u, v);
  wt /= ns;
endfunction

## a 32-bit integer hash (lowbias32: xor-shifts and multiplies mod 2^32),
## in doubles that hold the integers exactly
function x = hash32 (x)
  x = bitxor (x, floor (x / 2 ^ 16));
  x = mulmod (x, 2146121005);            # 0x7feb352d
  x = bitxor (x, floor (x / 2 ^ 15));
  x = mulmod (x, 2221713035);            # 0x846ca68b
  x = bitxor (x, floor (x / 2 ^ 16));
endfunction

## x c mod 2^32 for integers x, c < 2^32, exactly in doubles
function y = mulmod (x, c)
  ch = floor (c / 2 ^ 16);
  cl = c - ch * 2 ^ 16;
  y = mod (x * cl + mod (x * ch, 2 ^ 16) * 2 ^ 16, 2 ^ 32);
endfunction
