## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{u}, @var{v}] =} r2_points (@var{k}, @var{ns}, @var{seed}, @var{salt})
## The @var{ns} stratified uniforms of each pixel sample @var{k} (private,
## for @code{light_samples} and the BRDF samples of @code{scene_trace}):
## the first @var{ns} points of the R2 sequence (a rank-1 lattice of low
## discrepancy), shifted modulo 1 by two uniforms hashed from @var{k},
## @var{seed} and @var{salt} (a Cranley-Patterson rotation, independent
## from one pixel sample to the next: noise, not the lattice's pattern).
## @var{u}, @var{v}: ns*m x 1, the samples of k(1) first.  @var{salt} 0 is
## the light's; another salt gives independent points.
## @end deftypefn
function [u, v] = r2_points (k, ns, seed, salt = 0)
  j = (0:ns-1).';
  a1 = 0.7548776662466927;
  a2 = 0.5698402909980532;
  x = mod (double (k(:)).' + double (seed) * 2654435769, 2 ^ 32);     # 1 x m
  if (salt != 0)
    x = mod (hash32 (x) + salt, 2 ^ 32);
  endif
  h1 = hash32 (x);
  h2 = hash32 (mod (h1 + 1013904223, 2 ^ 32));
  u = mod (0.5 + j * a1 + (h1 + 0.5) / 2 ^ 32, 1);                  # ns x m
  v = mod (0.5 + j * a2 + (h2 + 0.5) / 2 ^ 32, 1);
  u = u(:);
  v = v(:);
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
