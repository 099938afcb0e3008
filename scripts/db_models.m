## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{L}, @var{S}] =} db_models (@var{L}, @var{c}, @var{D}, @var{ok}, @var{mats}, @var{X})
## The model comparison of `make database`'s report (db_report): appends
## the section "Models compared" to the lines @var{L} of report.md and
## returns its numbers @var{S} for summary.json.  @var{c}: repro_config;
## @var{D}: the materials' records as db_report reads them; @var{ok}: the
## processed materials (indices into @var{mats}); @var{X}: the measures,
## @code{X.flip.verdict.METHOD} (materials x lobes: the measure every
## verdict is made on, held out when there are held-out lights),
## @code{X.deltae.verdict}, @code{X.psnr.verdict} and the label
## @code{X.verdict}.
##
## Each model type of MODELS is fitted by every method of METHODS
## (repro_method); a model's fit of a material at a lobe count is its
## best over those methods by the verdict's measure (repro_models).
## The section gives, per material, the best model at each lobe count; per
## model and lobe count the numbers a model holds (the fit record's
## @code{params}: its type's fields) and their bytes as doubles (8 bytes
## each) beside the median size of the JSON file, the median FLIP over all
## materials, over the metals (METALS) and over the others, the median ΔE
## of the same fits, on how many materials the model is the best, and how
## often its unconstrained fit reflects more than it receives (the record's
## @code{albedo} above 1: brdf_fit reports it for the physically based
## types, not for Lafortune's); and the materials where the Lafortune model
## loses (another model's best FLIP lower than Lafortune's), and by how much.
## @end deftypefn
function [L, S] = db_models (L, c, D, ok, mats, X)
  nk = numel (c.lobes);
  [M, B] = repro_models (c, X.flip.verdict);
  metal = ismember (mats, c.metals);
  metal = metal(:);
  isok = false (numel (mats), 1);
  isok(ok) = true;
  L{end+1} = "## Models compared";
  L{end+1} = "";
  L{end+1} = sprintf (["Models (MODELS): %s. Each is fitted by every method of METHODS (`brdf_fit`; the " ...
                       "method `scene` fits the Lafortune model, `scene_ggx` GGX with the same table and " ...
                       "options); a model's fit of a material at a lobe count is its best over those methods by " ...
                       "%s (every fit's numbers, in-sample and held out, are in `table.csv`). " ...
                       "Metals (METALS in config.mk): %s; the other %d processed materials are the non-metals."],
                      strjoin (arrayfun (@(m) sprintf ("%s (%s)", m.model, m.title), M, "uniformoutput", false), ", "),
                      X.verdict, names_or_none (mats(metal & isok)), nnz (! metal & isok));
  L{end+1} = "";
  ## (lists of structs as cells: jsonencode writes an empty struct array as
  ## a name without a value)
  S = struct ("models", {{M.model}}, "metals", {mats(metal & isok)}, "per_model", struct (),
              "best", {{}}, "lafortune_loses", {{}});
  if (isempty (ok))
    L{end+1} = "No material was processed.";
    L{end+1} = "";
    return;
  endif

  ## --- the best model per material and lobe count
  L{end+1} = "### The best model per material";
  L{end+1} = "";
  L{end+1} = "The model with the lowest FLIP at each lobe count, its FLIP and the method of that fit.";
  L{end+1} = "";
  hdr = "| material | metal |";
  for k = c.lobes
    hdr = [hdr sprintf(" %d lobe%s |", k, ifelse (k == 1, "", "s"))];
  endfor
  L{end+1} = hdr;
  L{end+1} = ["|---|---|" repmat("---|", 1, nk)];
  for i = ok
    s = sprintf ("| %s | %s |", mats{i}, ifelse (metal(i), "yes", "no"));
    for j = 1:nk
      if (isnan (B.flip(i,j)))
        s = [s " - |"];
      else
        s = [s sprintf(" **%s** %.3f (%s) |", B.model{i,j}, B.flip(i,j), B.method{i,j})];
      endif
    endfor
    L{end+1} = s;
    S.best{end+1} = struct ("material", mats{i}, "metal", metal(i), "model", {B.model(i,:)},
                            "method", {B.method(i,:)}, "flip", B.flip(i,:));
  endfor
  L{end+1} = "";

  ## --- medians per model and lobe count, metals and non-metals apart
  L{end+1} = "### Medians per model and lobe count";
  L{end+1} = "";
  L{end+1} = sprintf (["Parameters: the numbers a fitted model holds (its type's fields, every channel); bytes: " ...
                       "those as doubles (8 bytes each), beside the median size of its JSON file (`brdf_export`). " ...
                       "FLIP and ΔE: medians of each model's best fits (above) over the processed materials, the " ...
                       "metals (%d) and the non-metals (%d); best on: the materials where it is the best model. " ...
                       "Albedo > 1: the fits (materials x methods) whose largest directional albedo exceeds 1, " ...
                       "unconstrained fits that reflect more light than they receive (brdf_fit reports the albedo " ...
                       "of the physically based models; `-`: none reported)."],
                      nnz (metal & isok), nnz (! metal & isok));
  L{end+1} = "";
  L{end+1} = ["| model | lobes | parameters | bytes (doubles) | JSON (bytes) | median FLIP | metals | " ...
              "non-metals | median ΔE | best on | albedo > 1 |"];
  L{end+1} = "|---|---|---|---|---|---|---|---|---|---|---|";
  for t = 1:numel (M)
    s = struct ("model", M(t).model, "title", M(t).title, "methods", {M(t).methods},
                "params", nan (1, nk), "bytes", nan (1, nk), "json_bytes", nan (1, nk),
                "median_flip", nan (1, nk), "median_flip_metals", nan (1, nk),
                "median_flip_nonmetals", nan (1, nk), "median_deltae", nan (1, nk),
                "best_on", zeros (1, nk), "albedo_above_1", nan (1, nk), "albedo_fits", zeros (1, nk),
                "flip", M(t).flip);
    for j = 1:nk
      k = c.lobes(j);
      np = [];
      jb = [];
      nbad = 0;
      nfit = 0;
      for i = ok
        for m = M(t).methods
          r = D(i).rec.fit.(m{1});
          np(end+1) = at (r, "params", k);
          jb(end+1) = at (r, "json_bytes", k);
          if (isfield (r, "albedo") && rows (r.albedo) >= k)
            nfit += 1;
            nbad += any (r.albedo(k,:) > 1);
          endif
        endfor
      endfor
      de = nan (numel (mats), 1);
      for i = ok
        if (! isempty (M(t).method{i,j}))
          de(i) = X.deltae.verdict.(M(t).method{i,j})(i,j);
        endif
      endfor
      s.params(j) = median (np);
      s.bytes(j) = 8 * s.params(j);
      s.json_bytes(j) = median (jb);
      s.median_flip(j) = nanmed (M(t).flip(isok,j));
      s.median_flip_metals(j) = nanmed (M(t).flip(isok & metal,j));
      s.median_flip_nonmetals(j) = nanmed (M(t).flip(isok & ! metal,j));
      s.median_deltae(j) = nanmed (de(isok));
      s.best_on(j) = nnz (strcmp (B.model(isok,j), M(t).model));
      s.albedo_fits(j) = nfit;
      if (nfit > 0)
        s.albedo_above_1(j) = nbad;
        alb = sprintf ("%d of %d", nbad, nfit);
      else
        alb = "-";
      endif
      L{end+1} = sprintf ("| %s | %d | %g | %g | %.0f | %s | %s | %s | %s | %d of %d | %s |", M(t).model, k,
                          s.params(j), s.bytes(j), s.json_bytes(j), num (s.median_flip(j), "%.3f"),
                          num (s.median_flip_metals(j), "%.3f"), num (s.median_flip_nonmetals(j), "%.3f"),
                          num (s.median_deltae(j), "%.2f"), s.best_on(j), numel (ok), alb);
    endfor
    S.per_model.(M(t).model) = s;
  endfor
  L{end+1} = "";

  ## --- where the Lafortune model loses, and by how much
  L{end+1} = "### Where the Lafortune model loses";
  L{end+1} = "";
  la = find (strcmp ({M.model}, "lafortune"));
  if (isempty (la))
    L{end+1} = "The Lafortune model is not among MODELS.";
  elseif (numel (M) == 1)
    L{end+1} = ["Only the Lafortune model was fitted (MODELS = lafortune); " ...
                "`make database MODELS=\"lafortune cooktorrance ggx\"` compares it with others."];
  else
    A = M(la);
    lose = isok & (B.flip < A.flip);      # materials x lobes
    L{end+1} = sprintf (["At a lobe count, the Lafortune model loses on a material when another model's best fit " ...
                         "has a lower FLIP than Lafortune's best. It loses on %s of the %d processed materials " ...
                         "(%s lobes); on the metals on %s of %d, on the non-metals on %s of %d."],
                        strjoin (arrayfun (@(j) sprintf ("%d", nnz (lose(:,j))), 1:nk, "uniformoutput", false), " / "),
                        numel (ok), strjoin (arrayfun (@num2str, c.lobes, "uniformoutput", false), " / "),
                        strjoin (arrayfun (@(j) sprintf ("%d", nnz (lose(metal,j))), 1:nk, "uniformoutput", false), " / "),
                        nnz (metal & isok),
                        strjoin (arrayfun (@(j) sprintf ("%d", nnz (lose(! metal,j))), 1:nk, "uniformoutput", false), " / "),
                        nnz (! metal & isok));
    g = find (strcmp ({M.model}, "ggx"));
    if (! isempty (g))
      ## Lavoue et al.'s split: GGX ahead of Lafortune on metals, not on the rest
      mm = @(F, w) arrayfun (@(j) nanmed (F(isok & w,j)), 1:nk);
      gm = mm (M(g).flip, metal) < mm (A.flip, metal);
      gn = mm (M(g).flip, ! metal) < mm (A.flip, ! metal);
      S.split = struct ("ggx_better_metals", gm, "ggx_better_nonmetals", gn,
                        "appears", all (gm) && ! any (gn));
      L{end+1} = "";
      L{end+1} = sprintf (["Lavoué et al.'s split (GGX better than Lafortune on the metals and not on the rest), by " ...
                           "median %s at %s lobes: GGX better on the metals: %s; on the non-metals: %s. " ...
                           "The split %s."], X.verdict, strjoin (arrayfun (@num2str, c.lobes, "uniformoutput", false), " / "),
                          yesno (gm), yesno (gn), ifelse (S.split.appears, "appears", "does not appear"));
    endif
    if (any (lose(:)))
      L{end+1} = "";
      L{end+1} = ["| material | lobes | Lafortune: FLIP (method) | best: model, FLIP (method) | " ...
                  "FLIP lower by | PSNR (dB), Lafortune → best |"];
      L{end+1} = "|---|---|---|---|---|---|";
      for i = ok
        for j = find (lose(i,:))
          d = A.flip(i,j) - B.flip(i,j);
          L{end+1} = sprintf ("| %s | %d | %.3f (%s) | %s, %.3f (%s) | %.3f (%.0f %%) | %.2f → %.2f |",
                              mats{i}, c.lobes(j), A.flip(i,j), A.method{i,j}, B.model{i,j}, B.flip(i,j),
                              B.method{i,j}, d, 100 * d / A.flip(i,j), X.psnr.verdict.(A.method{i,j})(i,j),
                              X.psnr.verdict.(B.method{i,j})(i,j));
          S.lafortune_loses{end+1} = struct ("material", mats{i}, "lobes", c.lobes(j), "flip", A.flip(i,j),
                                             "method", A.method{i,j}, "winner", B.model{i,j},
                                             "winner_method", B.method{i,j}, "winner_flip", B.flip(i,j),
                                             "flip_gain", d);
        endfor
      endfor
    endif
  endif
  L{end+1} = "";
endfunction

## R.(F)(K), NaN when the record lacks it
function x = at (r, f, k)
  x = NaN;
  if (isfield (r, f) && numel (r.(f)) >= k)
    x = r.(f)(k);
  endif
endfunction

## the median of the finite values of X (NaN: none)
function m = nanmed (x)
  x = x(isfinite (x));
  m = NaN;
  if (! isempty (x))
    m = median (x);
  endif
endfunction

function s = num (x, fmt)
  s = "-";
  if (isfinite (x))
    s = sprintf (fmt, x);
  endif
endfunction

function s = yesno (v)
  s = strjoin (arrayfun (@(x) ifelse (x, "yes", "no"), v, "uniformoutput", false), " / ");
endfunction

function s = names_or_none (v)
  s = "none";
  if (! isempty (v))
    s = strjoin (v, ", ");
  endif
endfunction

function s = ifelse (c, a, b)
  if (c) s = a; else s = b; endif
endfunction
