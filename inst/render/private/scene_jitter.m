## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{j} =} scene_jitter (@var{scene})
## @code{scene.jitter} as a logical, true when the field is absent or empty
## (scenes made before the option): whether the pixel samples are jittered
## (private, for @code{rt_render} and @code{merl_scene}).
## @end deftypefn
function j = scene_jitter (scene)
  j = ! isfield (scene, "jitter") || isempty (scene.jitter) || logical (scene.jitter);
endfunction
