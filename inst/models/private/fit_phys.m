## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn  {} {[@var{f}, @var{J}] =} fit_phys ("eval", @var{D}, @var{u})
## @deftypefnx {} {[@var{lb}, @var{ub}] =} fit_phys ("bounds", @var{D}, @var{np})
## @deftypefnx {} {@var{P} =} fit_phys ("split", @var{D}, @var{u})
## @deftypefnx {} {@var{u} =} fit_phys ("join", @var{D}, @var{P})
## @deftypefnx {} {@var{X} =} fit_phys ("x", [], @var{S})
## @deftypefnx {} {[@var{j}, @var{xc}, @var{how}, @var{xr}, @var{jg}, @var{rep}] =} fit_phys ("groups", [], @var{X}, @var{wt}, @var{opt}, @var{coarse})
## @deftypefnx {} {@var{P} =} fit_phys ("params", @var{D}, @var{u}, @var{s})
## @deftypefnx {} {@var{z} =} fit_phys ("zero", @var{D})
## @deftypefnx {} {[@var{U}, @var{warmup}] =} fit_phys ("starts", @var{D}, @var{u}, @var{opt})
## @deftypefnx {} {@var{ok} =} fit_phys ("guard", @var{D}, @var{u})
## The fit's coordinates of a physically based model (private; D.def from
## model_def, D.nch channels, rows of D.x the groups, values channel after
## channel as fit_stack stacks them).  @var{u} = [rho_d (nch); lobe 1:
## ks (nch), shape; lobe 2: ...]: one amplitude per channel and one shape
## per lobe (with one channel: a channel's own model; with three: shape
## shared by R, G, B).  A shape parameter of scale "log" is moved as its
## logarithm (roughness and exponent stay > 0 and are fitted by their
## ratios), "lin" as it is.  "split" gives the model_core vector of each
## channel (columns of @var{P}), "join" the inverse; "x" what the model
## sees of each pair of the table @var{S}, X = [cos theta_i, cos theta_o,
## wi.wo] (the fit merges samples equal in it), and "groups" how (see
## groups below).  The rest serves fit_driver and fit_grow, as
## fit_lafortune does for Lafortune lobes: "params" the model_core vectors
## in the data's units (rho_d and ks times the data's scale @var{s} of each
## channel: the shape does not scale), "zero" a lobe of amplitude 0 at the
## first start shape, "starts" the candidate starts of one more lobe (no
## warm-up), "guard" whether a result is accepted; "region", "start" and
## "repair" are empty (no acceptance set, no given start, no repair).
## @end deftypefn

function varargout = fit_phys (what, D, arg, varargin)
  switch (what)
    case "x"                             # what the model sees of a pair
      S = arg;
      varargout = {[S.wi(:,3), S.wo(:,3), sum(S.wi .* S.wo, 2)]};
      return;
    case "groups"
      [varargout{1:6}] = groups (arg, varargin{:});
      return;
    case {"region", "start", "repair"}   # no acceptance set, given start or repair
      varargout = {[]};
      return;
  endswitch
  def = D.def;
  nch = D.nch;
  ns = numel (def.shape);
  logs = strcmp (def.scale, "log");
  per = nch + ns;
  switch (what)
    case "eval"
      u = arg;
      nl = (numel (u) - nch) / per;
      [P, dq] = split (u, nch, ns, nl, logs, def.lo(2:end), def.hi(2:end));
      G = rows (D.x);
      f = zeros (G * nch, 1);
      jac = nargout > 1;
      if (jac)
        J = zeros (G * nch, numel (u));
      endif
      for c = 1:nch
        r = (c-1)*G+1:c*G;
        if (jac)
          [f(r), Jc] = __lafortune_model_core__ (def, P(:,c), D.x);
          J(r,c) = Jc(:,1);
          for k = 1:nl
            i0 = nch + (k-1) * per;            # u's lobe k starts after i0
            j0 = 1 + (k-1) * (1 + ns);         # model_core's lobe k after j0
            J(r,i0+c) = Jc(:,j0+1);
            J(r,i0+nch+(1:ns)) += Jc(:,j0+1+(1:ns)) .* dq(k,:);
          endfor
        else
          f(r) = __lafortune_model_core__ (def, P(:,c), D.x);
        endif
      endfor
      varargout = {f};
      if (jac)
        varargout{2} = J;
      endif
    case "bounds"
      nl = (arg - nch) / per;
      lo = def.lo(2:end);
      hi = def.hi(2:end);
      lo(logs) = log (lo(logs));
      hi(logs) = log (hi(logs));
      lobe_lo = [def.lo(1) * ones(nch, 1); lo(:)];        # ks, then the shape
      lobe_hi = [def.hi(1) * ones(nch, 1); hi(:)];
      varargout = {[zeros(nch, 1); repmat(lobe_lo, nl, 1)], [Inf(nch, 1); repmat(lobe_hi, nl, 1)]};
    case "split"
      u = arg;
      nl = (numel (u) - nch) / per;
      varargout = {split(u, nch, ns, nl, logs, def.lo(2:end), def.hi(2:end))};
    case "join"
      P = arg;
      nl = (rows (P) - 1) / (1 + ns);
      u = zeros (nch + nl * per, 1);
      u(1:nch) = P(1,:).';
      for k = 1:nl
        i0 = nch + (k-1) * per;
        j0 = 1 + (k-1) * (1 + ns);
        u(i0+(1:nch)) = P(j0+1,:).';
        q = P(j0+1+(1:ns),1).';
        q(logs) = log (q(logs));
        u(i0+nch+(1:ns)) = q;
      endfor
      varargout = {u};
    case "params"
      nl = (numel (arg) - nch) / per;
      P = split (arg, nch, ns, nl, logs, def.lo(2:end), def.hi(2:end));
      amp = [1, 2 + (0:nl-1) * (1 + ns)];          # rho_d and each ks
      P(amp,:) .*= varargin{1};
      varargout = {P};
    case "zero"
      q = cellfun (@(s) s(1), def.starts(:));
      q(logs) = log (q(logs));
      varargout = {[zeros(nch, 1); q]};
    case "starts"
      varargout = {starts(D, arg, varargin{1}.tries), false};
    case "guard"
      varargout = {guard_ok(D, arg)};
  endswitch
endfunction

## each channel's model_core vector (columns) and dq/du per lobe (rows)
function [P, dq] = split (u, nch, ns, nl, logs, lo, hi)
  per = nch + ns;
  P = zeros (1 + nl * (1 + ns), nch);
  dq = ones (nl, ns);
  P(1,:) = u(1:nch).';
  for k = 1:nl
    i0 = nch + (k-1) * per;
    j0 = 1 + (k-1) * (1 + ns);
    q = u(i0+nch+(1:ns)).';
    q(logs) = exp (q(logs));
    q = min (max (q, lo), hi);               # exp (log (hi)) may round above hi
    dq(k,logs) = q(logs);
    P(j0+1,:) = u(i0+(1:nch)).';
    P(j0+1+(1:ns),:) = q.' .* ones (1, nch);
  endfor
endfunction

## Starts for one more lobe on top of U: every shape of the type's grid
## with its best amplitude per channel and change of rho_d (linear least
## squares on the linearised data, as fit_starts does for Lafortune lobes);
## the TRIES best
function U = starts (D, u, tries)
  def = D.def;
  nch = D.nch;
  G = rows (D.x);
  grid = def.starts;
  [c{1:numel (grid)}] = ndgrid (grid{:});
  Q = cell2mat (cellfun (@(x) x(:), c, "uniformoutput", false));
  fcur = fit_eval (D, u);
  rho = u(1:nch);
  obj = inf (rows (Q), 1);
  S = zeros (nch, rows (Q));
  Dd = zeros (nch, rows (Q));
  for i = 1:rows (Q)
    g = def.lobe (D.x, Q(i,:));
    if (! all (isfinite (g)) || ! any (g > 0))
      continue;
    endif
    F = fcur;
    for ch = 1:nch
      r = (ch-1)*G+1:ch*G;
      w = D.wl(r) .^ 2;
      res = D.yl(r) - fcur(r);
      S1 = sum (w); Sr = sum (w .* res); Sg = sum (w .* g); Sgg = sum (w .* g .^ 2);
      Sgr = sum (w .* g .* res);
      dt = S1 * Sgg - Sg ^ 2;
      s = (S1 * Sgr - Sg * Sr) / dt;
      d = (Sr - s * Sg) / S1;
      if (! (dt > 0 && s > 0 && d >= -rho(ch) / pi))
        s = max (Sgr / max (Sgg, realmin), 0);
        d = 0;
      endif
      S(ch,i) = s;
      Dd(ch,i) = d;
      F(r) += d + s * g;
    endfor
    obj(i) = fit_objective (D, F);
  endfor
  ok = find (isfinite (obj) & any (S > 0, 1).');
  [~, o] = sort (obj(ok));
  ok = ok(o(1:min (tries, numel (o))));
  U = zeros (numel (u) + nch + numel (def.shape), numel (ok));
  logs = strcmp (def.scale, "log");
  for i = 1:numel (ok)
    q = Q(ok(i),:);
    q(logs) = log (q(logs));
    U(:,i) = [max(rho + pi * Dd(:,ok(i)), 0); u(nch+1:end); S(:,ok(i)); q(:)];
  endfor
endfunction

## The model of U finite and at most 10 times the data's maximum on the
## data's groups, on every channel.  (Lafortune's guard also checks a grid
## between the samples, where a Lafortune lobe, whose amplitude enters
## through its base, can explode; these lobes are normalised shapes with
## bounded parameters, and a true microfacet lobe legitimately exceeds the
## data's maximum at grazing mirror angles the data do not sample: that
## check rejected exact fits.)
function ok = guard_ok (D, u)
  P = fit_phys ("split", D, u);
  ok = all (isfinite (u));
  for c = 1:D.nch
    g = __lafortune_model_core__ (D.def, P(:,c), D.x);
    ok = ok && all (isfinite (g)) && max (g) <= 10 * max (D.ymax(c), realmin);
  endfor
endfunction

## The groups the fit runs on: samples equal in X = [cos ti, cos to, wi.wo]
## (exact), or, with more than AUTO_GROUPS samples (or as "reduce" says), cells
## of an n x n x n grid over (sqrt (theta_h), theta_d, |cos ti - cos to|)
## (MERL's own spacing of theta_h: fine near the mirror direction) at the
## weighted mean of their samples' X, taken with cos ti <= cos to (every model
## here is reciprocal: f (wi, wo) = f (wo, wi)).  No coarser grid: the
## starts are not screened (the groups themselves are returned as XR, with
## JG and REP the identity)
function [j, xc, how, xr, jg, rep] = groups (X, wt, opt, ~)
  AUTO_GROUPS = 20000;
  AUTO_GRID = 64;
  n = Inf;
  if (isnumeric (opt.reduce))
    n = opt.reduce;
  elseif (strcmp (opt.reduce, "auto") && rows (X) > AUTO_GROUPS)
    n = AUTO_GRID;
  endif
  if (isinf (n))
    [j, xc] = fit_reduce (X, wt, Inf);
    how = "exact";
  else
    G = brdf_geom (X);
    key = [floor(sqrt (acos (min (G.ch, 1)) / (pi/2)) * n), floor(acos (G.cd) / (pi/2) * n), ...
           floor(abs (X(:,1) - X(:,2)) * n)];
    [~, ~, j] = unique (min (key, n - 1), "rows");
    Xs = [min(X(:,1), X(:,2)), max(X(:,1), X(:,2)), X(:,3)];
    W = accumarray (j, wt);
    xc = [accumarray(j, wt .* Xs(:,1)), accumarray(j, wt .* Xs(:,2)), accumarray(j, wt .* Xs(:,3))] ./ W;
    how = sprintf ("grid %d", n);
  endif
  xr = xc;
  jg = rep = (1:rows (xc))';
endfunction
