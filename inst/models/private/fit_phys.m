## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn  {} {[@var{f}, @var{J}] =} fit_phys ("eval", @var{D}, @var{u})
## @deftypefnx {} {[@var{lb}, @var{ub}] =} fit_phys ("bounds", @var{D}, @var{np})
## @deftypefnx {} {@var{P} =} fit_phys ("split", @var{D}, @var{u})
## @deftypefnx {} {@var{u} =} fit_phys ("join", @var{D}, @var{P})
## @deftypefnx {} {@var{X} =} fit_phys ("x", [], @var{S})
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
## wi.wo] (the fit merges samples equal in it).
## @end deftypefn

function varargout = fit_phys (what, D, arg)
  if (strcmp (what, "x"))                # what the model sees of a pair
    S = arg;
    varargout = {[S.wi(:,3), S.wo(:,3), sum(S.wi .* S.wo, 2)]};
    return;
  endif
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
