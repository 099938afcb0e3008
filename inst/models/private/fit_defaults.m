## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## The defaults that depend on the table: for a scene table (merl_scene,
## S.kind "scene") the fit that looks best in that scene, as measured by
## FLIP and CIEDE2000 over a database of materials (README, "Fits that
## look right"); for a hemisphere table (merl_samples) the general fit, the
## one that looks best in light it was not made for (README, "One fit for
## every scene"): with the table's training views (S.views) the weighting
## chosen by them ("select": fit_select), without them log weights; for
## any other table, such as the in-plane one, the paper's fit (plain
## weights, each channel alone)
function opt = fit_defaults (opt, S)
  kind = "";
  if (isstruct (S) && isscalar (S) && isfield (S, "kind") && ischar (S.kind))
    kind = S.kind;
  endif
  scene = strcmp (kind, "scene");
  if (isempty (opt.weight))
    if (scene)
      opt.weight = "relative";
    elseif (strcmp (kind, "hemisphere") && isfield (S, "views") && ! isempty (S.views))
      opt.weight = "select";
    elseif (strcmp (kind, "hemisphere"))
      opt.weight = "log";
    else
      opt.weight = "plain";
    endif
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
