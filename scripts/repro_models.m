## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{M}, @var{B}] =} repro_models (@var{c}, @var{F})
## @deftypefnx {} {[@var{M}, @var{B}] =} repro_models (@var{c}, @var{F}, @var{floor})
## The models compared, for the reports of `make reproduce` and `make
## database`: the model types that the methods of @var{c} (repro_config)
## fit, and each one's best fit per material and lobe count.  @var{F} has
## one field per method of @code{c.methods}: the FLIP of its renders,
## materials x numel (c.lobes) (NaN where there is none); lower is better.
##
## @var{M}: struct array, one per model type in the order of MODELS (then
## any a method names itself), with @code{model} (the type),
## @code{title} (@code{brdf_model (type).title}), @code{methods} (its
## methods), @code{flip} (materials x lobes: the lowest FLIP over its
## methods) and @code{method} (materials x lobes cell: the method that gave
## it; "" where none).  @var{B}: the best model per material and lobe
## count over all of them, @code{flip}, @code{model}, @code{method} (same
## sizes).  Ties go to the first model, then the first method.
## @code{B.tied} (same size): the models whose best FLIP is within the
## noise floor @var{floor} (materials x 1, repro_judge's
## @code{noise_flip_mean}; NaN or absent: none measured) of the best,
## the best first, then the others in the order of @var{M}, joined by
## ", " (repro_tie): where it names more than one, the reports say these
## tie rather than name a best.
## @end deftypefn
function [M, B] = repro_models (c, F, floor)
  P = cellfun (@repro_method, c.methods);
  types = unique ([c.models(:)', {P.model}], "stable");
  types = types(ismember (types, {P.model}));
  n = rows (F.(c.methods{1}));
  nk = numel (c.lobes);
  M = struct ("model", types, "title", "", "methods", {{}}, "flip", [], "method", {{}});
  if (nargin < 3)
    floor = nan (n, 1);
  endif
  B = struct ("flip", nan (n, nk), "model", {repmat({""}, n, nk)}, "method", {repmat({""}, n, nk)},
              "tied", {repmat({""}, n, nk)});
  for t = 1:numel (types)
    M(t).title = brdf_model (types{t}).title;
    M(t).methods = c.methods(strcmp ({P.model}, types{t}));
    M(t).flip = nan (n, nk);
    M(t).method = repmat ({""}, n, nk);
    for m = M(t).methods
      x = F.(m{1});
      better = x < M(t).flip | (isnan (M(t).flip) & ! isnan (x));
      M(t).flip(better) = x(better);
      M(t).method(better) = m(1);
    endfor
    better = M(t).flip < B.flip | (isnan (B.flip) & ! isnan (M(t).flip));
    B.flip(better) = M(t).flip(better);
    B.model(better) = types(t);
    B.method(better) = M(t).method(better);
  endfor
  ## the models within the noise floor of the best: tied with it
  B.tied = B.model;
  for t = 1:numel (types)
    tie = repro_tie (M(t).flip, B.flip, floor(:)) & ! strcmp (B.model, types{t});
    B.tied(tie) = strcat (B.tied(tie), {", "}, types(t));
  endfor
endfunction
