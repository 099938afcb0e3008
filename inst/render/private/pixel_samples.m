## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{x}, @var{y}] =} pixel_samples (@var{H}, @var{W}, @var{k}, @var{spp}, @var{j})
## View coordinates (as @code{camera_rays} takes them) of the samples
## @var{k} (0-based column vector; sample k is pixel mod (k, H W) (column
## major) and its sample number floor (k / (H W))) of an H x W image with
## @var{spp} samples per pixel (private, for @code{rt_render} and
## @code{merl_scene}).
##
## The samples of a pixel are stratified: the pixel is cut into nx x ny
## cells, nx ny = @var{spp}, ny the largest divisor of @var{spp} not above
## its square root, and sample s lies in cell (mod (s, nx), floor (s / nx)),
## at the offset @var{j} (numel (k) x 2 in [0, 1): random for jittered
## samples, 0.5 for the cell centres).  With cell centres and
## @var{spp} = n^2 the samples are the regular n x n grid of POV-Ray's
## anti-aliasing @code{+AM1 +R@var{n}}.
## @end deftypefn
function [x, y] = pixel_samples (H, W, k, spp, j)
  npix = H * W;
  p = mod (k, npix);
  s = floor (k / npix);
  ny = spp;
  for d = floor (sqrt (spp)):-1:1
    if (mod (spp, d) == 0)
      ny = d;
      break;
    endif
  endfor
  nx = spp / ny;
  r = mod (p, H);                       # 0-based row (0 = top)
  c = floor (p / H);                    # 0-based column (0 = left)
  x = (c + (mod (s, nx) + j(:,1)) / nx) / W - 0.5;
  y = 0.5 - (r + (floor (s / nx) + j(:,2)) / ny) / H;
endfunction
