## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## The defaults that depend on the table: for a scene table (merl_scene,
## S.kind "scene") the fit that looks best in the picture, as measured by
## FLIP and CIEDE2000 on the 26 materials of ../shared (README, "Fits that
## look right"); for any other table the paper's fit (plain weights, each
## channel alone)
function opt = fit_defaults (opt, S)
  scene = isstruct (S) && isscalar (S) && isfield (S, "kind") && ischar (S.kind) && strcmp (S.kind, "scene");
  if (isempty (opt.weight))
    opt.weight = merge (scene, "relative", "plain");
  endif
  if (isempty (opt.color))
    opt.color = "separate";             # each channel alone, for every table
  endif
  if (isempty (opt.tries))
    ## a picture's error has local minima (a highlight fitted by the wrong
    ## lobe): for a scene table, and for the image's weights, every
    ## direction family is screened
    opt.tries = merge (scene || strcmp (opt.weight, "psnr"), Inf, 1);
  endif
endfunction
