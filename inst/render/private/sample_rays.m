## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{O}, @var{D}] =} sample_rays (@var{scene}, @var{cam}, @var{k}, @var{jitter})
## Camera rays of the pixel samples @var{k} (0-based column, see
## @code{pixel_samples}) of @var{scene} with camera @var{cam}: at random
## places in their cells (@code{rand}, whose state the caller seeds with
## @code{scene.seed}) when @var{jitter}, else at the cell centres (private,
## for @code{rt_render} and @code{merl_scene}, so both take the same
## samples).  Sample k gets the k-th pair of the random stream, so that the
## samples do not depend on how many are traced at once (rt_render's
## "chunk", merl_scene's own).  pixel_samples and __lafortune_camera_rays__
## are the definition; the oct-file __rt_rays__ makes the same rays, bit for
## bit, when it is built.
## @end deftypefn
function [O, D] = sample_rays (scene, cam, k, jitter)
  m = numel (k);
  if (jitter)
    j = rand (2, m).';     # sample k: the stream's pair k, whatever the chunk
  else
    j = 0.5 * ones (m, 2);
  endif
  [done, O, D] = __lafortune_oct_call__ ("__rt_rays__", "rt_render", scene.height, scene.width,
                                         k, scene.spp, j, ! strcmp (cam.type, "orthographic"),
                                         cam.eye, cam.f, cam.r, cam.u, cam.w, cam.h);
  if (! done)
    [x, y] = pixel_samples (scene.height, scene.width, k, scene.spp, j);
    [O, D] = __lafortune_camera_rays__ (cam, x, y);
  endif
endfunction
