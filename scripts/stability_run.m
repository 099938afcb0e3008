## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{r}, @var{names}] =} stability_run (@var{S}, @var{fitter})
## One fit of the stability checks: the table @var{S} through the fitter
## named @var{fitter} (@var{names}, with no argument, the names: "grow",
## lafortune_fit's growing 2-lobe fit; "plain", its paper's start; "shared",
## one lobe shape for R, G, B; "start", one lobe from a start that explodes
## at grazing angles; "ggx", brdf_fit's GGX, 1 lobe).  @var{r}: @code{what}
## (@qcode{"bounded"}: a finite model at most 10 times the data's largest
## finite value on the whole hemisphere (zero where the data are), GGX
## finite; @qcode{"error"}: an
## error whose id starts with "lafortune:"; else a defect, "unbounded" or
## "error without id"), @code{model}, @code{id}, @code{message},
## @code{ratio} (the model's bound over the data's maximum) and @code{time}.
## @end deftypefn
function [r, names] = stability_run (S, fitter)
  names = {"grow", "plain", "shared", "start", "ggx"};
  if (nargin == 0)
    r = names;
    return;
  endif
  boom = struct ("rho_d", [0.1 0.1 0.1], "Cxy", -[1.5 1.5 1.5], "Cz", [0.9 0.9 0.9],
                 "e", [300 300 300]);
  r = struct ("what", "bounded", "model", [], "id", "", "message", "", "ratio", NaN, "time", 0);
  ws = warning ("off", "lafortune:notConverged");
  t0 = tic ();
  try
    switch (fitter)
      case "grow"
        r.model = lafortune_fit (S, 2);
      case "plain"
        r.model = lafortune_fit (S, 2, "init", "plain");
      case "shared"
        r.model = lafortune_fit (S, 2, "color", "shared");
      case "start"
        r.model = lafortune_fit (S, 1, "start", boom);
      case "ggx"
        r.model = brdf_fit (S, "ggx", 1);
    endswitch
  catch err
    r.what = "error";
    r.id = err.identifier;
    r.message = err.message;
    if (! strncmp (err.identifier, "lafortune:", 10))
      r.what = "error without id";
    endif
  end_try_catch
  r.time = toc (t0);
  warning (ws);
  if (! isempty (r.model))
    y = S.rgb;
    y(! isfinite (y)) = 0;
    ymax = max (abs (y), [], 1);
    pk = __lafortune_check_bounded__ (r.model);
    r.ratio = max (pk(ymax > 0) ./ ymax(ymax > 0));
    if (isempty (r.ratio))
      r.ratio = max (pk);
    endif
    lim = 10 * (1 + 1e-9);
    over = ! (pk <= lim * ymax);
    if (! all (isfinite (pk)) || (! strcmp (fitter, "ggx") && any (over)))
      r.what = "unbounded";
    endif
  endif
endfunction
