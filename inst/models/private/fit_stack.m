## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{D} =} fit_stack (@var{Ds}, @var{ref})
## The data of several channels (a cell of fit_data structs on the same
## groups, in the same scaled units) as one problem (private): for lobes
## shared across the channels (shared_lobes), fitted by one leasqr run.
## The rows are channel after channel: @code{w}, @code{ty}, @code{wl},
## @code{yl} stacked, @code{wsw} and @code{ymax} one per channel, @code{t}
## and @code{dt} applied per channel.  The metric's divisor @code{n} is the
## same for every channel (metric_spec), so the objective is the sum of
## the channels' sums of squares, as the metric's finish adds them.
## @code{nch} is the number of channels and @code{ref} the reference
## channel's position among them.
## @end deftypefn
function D = fit_stack (Ds, ref)
  nch = numel (Ds);
  D = Ds{1};
  D.nch = nch;
  D.ref = ref;
  cat_f = @(f) cell2mat (cellfun (@(d) d.(f), Ds(:), "uniformoutput", false));
  D.w = cat_f ("w");
  D.ty = cat_f ("ty");
  D.wl = cat_f ("wl");
  D.yl = cat_f ("yl");
  D.wsw = cellfun (@(d) d.wsw, Ds);
  D.ymax = cellfun (@(d) d.ymax, Ds);
  cs = cellfun (@(d) d.c, Ds);
  G = rows (D.x);
  D.c = cs;
  if (! D.identity)
    t = Ds{1}.t;
    dt = Ds{1}.dt;
    D.t = @(f, c) blocks (t, f, cs, G);
    D.dt = @(f, c) blocks (dt, f, cs, G);
  endif
  if (isfield (D, "P"))
    Ps = cellfun (@(d) d.P, Ds, "uniformoutput", false);
    D.P = fit_stack (Ps, ref);
  endif
endfunction

## H (F, c) channel by channel on the blocks of G rows of F (columns kept)
function Y = blocks (h, F, cs, G)
  Y = F;
  for i = 1:numel (cs)
    r = (i-1)*G+1:i*G;
    Y(r,:) = h (F(r,:), cs(i));
  endfor
endfunction
