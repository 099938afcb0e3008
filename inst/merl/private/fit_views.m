## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn {} {@var{V} =} fit_views (@var{material})
## The training views of the general fit (private; @code{merl_samples}
## attaches them to its table, @code{fit_select} chooses by them): a
## 64 x 64 sphere, 2 samples per pixel, lit by three directional lights
## (scene_make's default, from the right, from the left and above).
## None of them is a light the pipelines judge by (their held-out lights,
## JUDGE, are light probes and a light from behind).  @var{V} is a struct
## array with @code{scene}, @code{cache} (rt_render's trace) and @code{ref}
## (@var{material} rendered there).
## @end deftypefn

function V = fit_views (material)
  sz = [64 64];
  sc = {scene_make("sphere", "size", sz, "spp", 2),
        scene_make("sphere", "size", sz, "spp", 2, "light_direction", [1 0.3 0.6]),
        scene_make("sphere", "size", sz, "spp", 2, "light_direction", [-0.6 0.5 0.6])};
  V = struct ("scene", sc(:)', "cache", [], "ref", []);
  for i = 1:numel (V)
    [V(i).ref, ~, V(i).cache] = rt_render (V(i).scene, material, "progress", false);
  endfor
endfunction
