## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn  {} {[@var{f}, @var{J}] =} fit_lafortune ("eval", @var{D}, @var{p})
## @deftypefnx {} {[@var{lb}, @var{ub}] =} fit_lafortune ("bounds", @var{D}, @var{np})
## @deftypefnx {} {@var{x} =} fit_lafortune ("x", [], @var{S})
## @deftypefnx {} {[@var{j}, @var{xc}, @var{how}, @var{xr}, @var{jg}, @var{rep}] =} fit_lafortune ("groups", [], @var{x}, @var{wt}, @var{opt}, @var{coarse})
## @deftypefnx {} {@var{G} =} fit_lafortune ("region", [])
## @deftypefnx {} {@var{ok} =} fit_lafortune ("guard", @var{D}, @var{p}, @var{G})
## @deftypefnx {} {@var{p} =} fit_lafortune ("repair", @var{D}, @var{p})
## @deftypefnx {} {@var{p0} =} fit_lafortune ("start", @var{D}, @var{opt}, @var{B}, @var{s}, @var{nlobes})
## @deftypefnx {} {[@var{P}, @var{warmup}] =} fit_lafortune ("starts", @var{D}, @var{p}, @var{opt}, @var{R})
## @deftypefnx {} {@var{z} =} fit_lafortune ("zero", @var{D})
## @deftypefnx {} {@var{P} =} fit_lafortune ("params", @var{D}, @var{p}, @var{s})
## The fit's coordinates of the Lafortune model (private; its definition's
## @code{coords}, as fit_phys is the physically based types'), for
## fit_driver and fit_grow.  One channel's parameters are [rho_d; Cxy; Cz;
## e; ...]; with @code{D.nch} > 1, lobes shared across the channels
## (shared_lobes).
##
## "eval": the values (and Jacobian) at the groups (a, c) = @code{D.x}
## (lafortune_core).  "bounds": rho_d >= 0 and each lobe field within the
## definition's @code{lo} and @code{hi}.  "x": what the model sees of each
## pair of the table @var{S}, (a, c) = (ux vx + uy vy, uz vz).  "groups":
## samples equal in (a, c) merged (fit_reduce), or on the cells of a 512 x
## 512 grid when there are many, and for a growing fit (@var{coarse}) a
## coarser grid that screens starts (see groups below).  "region": the
## acceptance set (fit_guard): the plane of incidence to 90 degrees, which
## reaches every lobe's largest value on the hemisphere, whatever the table
## covers.  "guard": the parameters accepted on every channel.  "repair":
## one channel's parameters with the lobes that exceed the guard's bound
## scaled down to it (fit_guard); [] for shared lobes, which are not
## repaired.  "start": the given start @code{opt.start} (a model, data
## units), or the paper's plain start with @code{opt.init} "plain", in fit
## coordinates for data divided by @var{s}; [] for a growing fit.
## "starts": the candidate lobes on top of @var{p} (fit_starts), and
## whether a warm-up on the coarse grid @var{R} pays.  "zero": a lobe that
## is zero.  "params": parameters fitted to data divided by @var{s} in the
## data's units, one column per channel: rho_d times @var{s}, each lobe's
## Cxy and Cz times @var{s}^(1/e) (a lobe with e = 0, a step, cannot be
## scaled and stays), so that the model is @var{s} times the fitted one.
## @end deftypefn

function varargout = fit_lafortune (what, D, varargin)
  switch (what)
    case "eval"
      p = varargin{1};
      if (D.nch == 1)
        [varargout{1:max (nargout, 1)}] = __lafortune_lafortune_core__ (p, D.x(:,1), D.x(:,2));
      else
        [varargout{1:max (nargout, 1)}] = shared_lobes ("eval", p, D.ref, D.nch, D.x(:,1), D.x(:,2));
      endif
    case "bounds"
      np = varargin{1};
      if (D.nch == 1)
        nl = (np - 1) / 3;
        varargout = {[0; repmat(D.def.lo(:), nl, 1)], [Inf; repmat(D.def.hi(:), nl, 1)]};
      else
        [varargout{1:2}] = shared_lobes ("bounds", np, D.nch);
      endif
    case "x"
      S = varargin{1};
      varargout = {[S.wi(:,1) .* S.wo(:,1) + S.wi(:,2) .* S.wo(:,2), S.wi(:,3) .* S.wo(:,3)]};
    case "groups"
      [varargout{1:6}] = groups (varargin{:});
    case "region"
      varargout = {fit_guard()};
    case "guard"
      varargout = {accepted(D, varargin{:})};
    case "repair"
      varargout = {[]};
      if (D.nch == 1)
        varargout = {fit_guard("repair", varargin{1}, D.ymax)};
      endif
    case "start"
      varargout = {start(D, varargin{:})};
    case "starts"
      [varargout{1:2}] = starts (D, varargin{:});
    case "zero"
      varargout = {[0; 0; 1; zeros(D.nch - 1, 1)]};
    case "params"
      [p, s] = varargin{:};
      p = rescale (D, p, s(1));
      if (D.nch > 1)
        p = cell2mat (shared_lobes ("split", p, D.ref, D.nch));
      endif
      varargout = {p};
  endswitch
endfunction

## parameters P fitted to data divided by S in the data's units: one
## channel's (unscale), or shared lobes' (shared_lobes)
function p = rescale (D, p, s)
  if (D.nch == 1)
    p = unscale (p, s);
  else
    p = shared_lobes ("unscale", p, s, D.ref, D.nch);
  endif
endfunction

## one channel's parameters P fitted to data divided by S, in the data's units
function p = unscale (p, s)
  if (s == 1)
    return;
  endif
  p(1) *= s;
  for k = 1:(numel (p) - 1) / 3
    e = p(3*k+1);
    f = exp (log (s) / e);
    if (e > 0 && isfinite (f) && f > 0)
      p(3*k-1:3*k) *= f;
    endif
  endfor
endfunction

## The guard (fit_guard) on every channel of the parameters P of D
function ok = accepted (D, p, G)
  if (D.nch == 1)
    ok = fit_guard (p, G, D.ymax);
    return;
  endif
  P = shared_lobes ("split", p, D.ref, D.nch);
  ok = true;
  for c = 1:D.nch
    ok = ok && fit_guard (P{c}, G, D.ymax(c));
  endfor
endfunction

## The start of the channels B (data divided by S): the given model's, or
## the paper's naive start: rho_d = 0.1, lobe k: Cxy = -1, Cz = 1, e = 10 k
## (for shared lobes, every channel's amplitude 1); none for a growing fit
function p0 = start (D, opt, B, s, nlobes)
  p0 = [];
  nch = numel (B);
  if (! isempty (opt.start))
    P = arrayfun (@(c) __lafortune_model_pack__ (opt.start, D.def, c), B, "uniformoutput", false);
    if (nch == 1)
      p0 = P{1};
    else
      p0 = shared_lobes ("join", P, D.ref);
    endif
    p0 = rescale (D, p0, 1 / s(1));
  elseif (strcmp (opt.init, "plain"))
    lobe = [-1; 1; 0; ones(nch - 1, 1)];
    p0 = [0.1 * ones(nch, 1); repmat(lobe, nlobes, 1)];
    p0(nch+3:2+nch:end) = 10 * (1:nlobes);
    p0 = rescale (D, p0, 1 / s(1));
  endif
endfunction

## The candidate lobes on top of P (fit_starts on the coarse grid R), and
## whether a warm-up run on R pays: only when R is much smaller than D and
## an iteration on D costs much more than leasqr's fixed cost per
## iteration (WARMUP_COST, in groups x parameters^2, an SVD's cost: the
## README's "Measurements behind the design" says where it was set).
## Without one, the best start is refined on R (fit_starts)
function [P, warmup] = starts (D, p, opt, R)
  WARMUP_COST = 2e5;
  np = numel (p) + 2 + D.nch;
  warmup = 4 * rows (R.x) < rows (D.x) && rows (D.ty) * np ^ 2 > WARMUP_COST;
  P = fit_starts (R, p, ! warmup);
endfunction

## The groups the fit runs on (J, XC: exact equal (a, c) pairs, or grid
## cells when there are more than AUTO_GROUPS samples, or as "reduce" says)
## and the coarse grid that screens starts (JG: each group's cell, XR: the
## cells' positions; about "screen_samples" cells, or the groups themselves
## when there are no more than that, or when COARSE is false), and for each
## cell the group nearest its position (REP), which stands for it in
## fit_data's coarse data.
function [j, xc, how, xr, jg, rep] = groups (x, wt, opt, coarse)
  AUTO_GROUPS = 20000;
  AUTO_GRID = 512;
  if (isnumeric (opt.reduce))
    n = opt.reduce;
  elseif (strcmp (opt.reduce, "auto") && rows (x) > AUTO_GROUPS)
    n = AUTO_GRID;
  else
    n = Inf;
  endif
  [j, xc] = fit_reduce (x, wt, n);
  if (isinf (n))
    how = "exact";
  else
    how = sprintf ("grid %d", n);
  endif
  xr = xc; jg = (1:rows (xc))'; rep = jg;
  if (coarse && rows (xc) > opt.screen_samples)
    ## coarsen the groups (cells of about the wanted count)
    gw = accumarray (j, wt);
    n = 2 ^ ceil (log2 (sqrt (opt.screen_samples)));
    while (true)
      [jg, xr] = fit_reduce (xc, gw, n);
      if (rows (xr) >= opt.screen_samples / 2 || n >= 4096)
        break;
      endif
      n *= 2;
    endwhile
    d = sum ((xc - xr(jg,:)) .^ 2, 2);
    [~, o] = sortrows ([jg d]);
    first = true (numel (o), 1);
    first(2:end) = jg(o(2:end)) != jg(o(1:end-1));
    rep = zeros (rows (xr), 1);
    rep(jg(o(first))) = o(first);
  endif
endfunction
