## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{S} =} db_models (@var{c}, @var{D}, @var{ok}, @var{mats}, @var{X})
## The numbers of the models compared in `make database`'s summary
## (db_summary), for summary.json and the report's section "Models
## compared".  @var{c}: repro_config; @var{D}: the materials' records as
## db_report reads them; @var{ok}: the processed materials (indices into
## @var{mats}); @var{X}: the measures, @code{X.flip.verdict.METHOD}
## (materials x lobes: the measure every verdict is made on, held out when
## there are held-out lights), @code{X.deltae.verdict},
## @code{X.psnr.verdict}, and @code{X.noise} (materials x 1: the
## verdicts' noise floor, db_summary).
##
## Each model type of MODELS is fitted by every method of METHODS
## (repro_method); a model's fit of a material at a lobe count is its
## best over those methods by the verdict's measure (repro_models).
## @var{S} gives per material the best model at each lobe count
## (@code{best}, with @code{tied}: the models within the material's noise
## floor of it, repro_models); per model and lobe count (@code{per_model}) the numbers a
## model holds (the fit record's @code{params}: its type's fields) and
## their bytes as doubles beside the median size of the JSON file, the
## median FLIP over all materials, over the metals (METALS) and over the
## others, the median ΔE of the same fits, on how many materials the model
## is the best, and how often its unconstrained fit reflects more than it
## receives (the record's @code{albedo} above 1: brdf_fit reports it for
## the physically based types, not for Lafortune's); where the Lafortune
## model loses (another model's best FLIP lower than Lafortune's by more
## than the noise floor: within it they tie), by how
## much (@code{lafortune_loses}) and how often (@code{loses}), and
## Lavoué et al.'s split (@code{split}: GGX better on the metals only).
## @end deftypefn
function S = db_models (c, D, ok, mats, X)
  nk = numel (c.lobes);
  [M, B] = repro_models (c, X.flip.verdict, X.noise);
  metal = ismember (mats, c.metals);
  metal = metal(:);
  isok = false (numel (mats), 1);
  isok(ok) = true;
  ## (lists of structs as cells: jsonencode writes an empty struct array as
  ## a name without a value)
  S = struct ("models", {{M.model}}, "metals", {mats(metal & isok)}, "per_model", struct (),
              "best", {{}}, "lafortune_loses", {{}}, "titles", {{M.title}},
              "n_metals", nnz (metal & isok), "n_nonmetals", nnz (! metal & isok));
  if (isempty (ok))
    return;
  endif
  for i = ok
    S.best{end+1} = struct ("material", mats{i}, "metal", metal(i), "model", {B.model(i,:)},
                            "method", {B.method(i,:)}, "flip", B.flip(i,:), "tied", {B.tied(i,:)},
                            "noise_flip", X.noise(i));
  endfor
  for t = 1:numel (M)
    S.per_model.(M(t).model) = per_model (c, D, ok, X, M(t), B, metal, isok);
  endfor
  ## where the Lafortune model loses, and by how much
  la = find (strcmp ({M.model}, "lafortune"));
  if (isempty (la) || numel (M) == 1)
    return;
  endif
  A = M(la);
  lose = isok & (B.flip < A.flip) & ! repro_tie (B.flip, A.flip, X.noise(:));  # materials x lobes
  S.loses = struct ("all", sum (lose, 1), "metals", sum (lose(metal,:), 1), "nonmetals", sum (lose(! metal,:), 1));
  g = find (strcmp ({M.model}, "ggx"));
  if (! isempty (g))
    ## Lavoue et al.'s split: GGX ahead of Lafortune on metals, not on the rest
    mm = @(F, w) arrayfun (@(j) repro_median (F(isok & w,j)), 1:nk);
    gm = mm (M(g).flip, metal) < mm (A.flip, metal);
    gn = mm (M(g).flip, ! metal) < mm (A.flip, ! metal);
    S.split = struct ("ggx_better_metals", gm, "ggx_better_nonmetals", gn,
                      "appears", all (gm) && ! any (gn));
  endif
  for i = ok
    for j = find (lose(i,:))
      d = A.flip(i,j) - B.flip(i,j);
      S.lafortune_loses{end+1} = struct ("material", mats{i}, "lobes", c.lobes(j), "flip", A.flip(i,j),
                                         "method", A.method{i,j}, "winner", B.model{i,j},
                                         "winner_method", B.method{i,j}, "winner_flip", B.flip(i,j),
                                         "flip_gain", d, "flip_gain_pct", 100 * d / A.flip(i,j),
                                         "psnr", X.psnr.verdict.(A.method{i,j})(i,j),
                                         "winner_psnr", X.psnr.verdict.(B.method{i,j})(i,j));
    endfor
  endfor
endfunction

## the medians of model M's best fits per lobe count: its size, FLIP over
## all materials, the metals and the others, ΔE, how often it is the best,
## how many of its fits reflect more than they receive
function s = per_model (c, D, ok, X, M, B, metal, isok)
  nk = numel (c.lobes);
  s = struct ("model", M.model, "title", M.title, "methods", {M.methods},
              "params", nan (1, nk), "bytes", nan (1, nk), "json_bytes", nan (1, nk),
              "median_flip", nan (1, nk), "median_flip_metals", nan (1, nk),
              "median_flip_nonmetals", nan (1, nk), "median_deltae", nan (1, nk),
              "best_on", zeros (1, nk), "albedo_above_1", nan (1, nk), "albedo_fits", zeros (1, nk),
              "flip", M.flip);
  for j = 1:nk
    k = c.lobes(j);
    np = [];
    jb = [];
    nbad = 0;
    nfit = 0;
    for i = ok
      for m = M.methods
        r = D(i).rec.fit.(m{1});
        np(end+1) = at (r, "params", k);
        jb(end+1) = at (r, "json_bytes", k);
        if (isfield (r, "albedo") && rows (r.albedo) >= k)
          nfit += 1;
          nbad += any (r.albedo(k,:) > 1);
        endif
      endfor
    endfor
    de = nan (numel (isok), 1);
    for i = ok
      if (! isempty (M.method{i,j}))
        de(i) = X.deltae.verdict.(M.method{i,j})(i,j);
      endif
    endfor
    s.params(j) = median (np);
    s.bytes(j) = 8 * s.params(j);
    s.json_bytes(j) = median (jb);
    s.median_flip(j) = repro_median (M.flip(isok,j));
    s.median_flip_metals(j) = repro_median (M.flip(isok & metal,j));
    s.median_flip_nonmetals(j) = repro_median (M.flip(isok & ! metal,j));
    s.median_deltae(j) = repro_median (de(isok));
    s.best_on(j) = nnz (strcmp (B.model(isok,j), M.model));
    s.albedo_fits(j) = nfit;
    if (nfit > 0)
      s.albedo_above_1(j) = nbad;
    endif
  endfor
endfunction

## R.(F)(K), NaN when the record lacks it
function x = at (r, f, k)
  x = NaN;
  if (isfield (r, f) && numel (r.(f)) >= k)
    x = r.(f)(k);
  endif
endfunction
