## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{rgb} =} merl_eval (@var{brdf}, @var{wi}, @var{wo})
## @deftypefnx {lafortune} {@var{rgb} =} merl_eval (@var{brdf}, @var{wi}, @var{wo}, @var{method})
## @deftypefnx {lafortune} {[@var{rgb}, @var{valid}] =} merl_eval (@dots{})
## Look up a MERL material for pairs of directions.
##
## @var{brdf} is a struct from @code{merl_read} or @code{merl_synth}.
## @var{wi} (toward the light) and @var{wo} (toward the viewer) are N x 3 unit
## directions in the local frame (z = normal); a 1 x 3 array is expanded.
## @var{rgb} is N x 3.
##
## @var{method} @code{"nearest"} (default) picks the bin exactly as the
## database's own reference reader does: half/difference angles with phi_h
## removed, theta_h index floor (sqrt (theta_h/(pi/2)) * 90), theta_d index
## floor (theta_d/(pi/2) * 90), phi_d folded into [0, pi) by reciprocity and
## index floor (phi_d/pi * 180), each clamped.  It runs in the compiled
## @code{__merl_nearest__} (@file{src/}, built by @code{pkg install}): a fast
## path (half and difference vectors compared with tables of the bin edges)
## places most samples; those within 1e-6 of a bin edge, with the half
## vector along the normal or with wi close to wo (where phi_h or phi_d is
## the atan2 of rounding residues) are placed with the reader's own sequence
## of operations (its Rodrigues rotations, term by term), so that even the
## samples that rounding decides land in the reader's bin for the same
## direction vectors.  @code{"reference"} does every sample with the
## reader's arithmetic, in Octave: the same bins, slower (bench_merl, the
## peer of the benchmark; @code{"nearest"} falls back to it, with the
## warning @code{lafortune:noOctFile} once, when the oct-file has not been
## built).  @code{"linear"} interpolates
## trilinearly in that index space (bin k holds the value at index k; phi_d
## wraps around), using only valid neighbours.
##
## Directions below the horizon give 0.  Invalid (missing) samples give 0 and
## @code{false} in the optional output @var{valid} (N x 1).
##
## @example
## @group
## brdf = merl_standin ("red-plastic");
## t = (0:10:80)' * pi / 180;
## wi = [sin(t) 0*t cos(t)];
## rgb = merl_eval (brdf, wi, [-wi(:,1:2) wi(:,3)])   # mirror directions
## @end group
## @end example
## @seealso{merl_read, merl_plane, lafortune_eval}
## @end deftypefn
function [rgb, valid] = merl_eval (brdf, wi, wo, method = "nearest")
  if (nargin < 3 || nargin > 4)
    print_usage ();
  endif
  __lafortune_check_merl__ (brdf, "merl_eval");
  [wi, wo] = __lafortune_check_dirs__ (wi, wo, "merl_eval");
  if (! ischar (method) || ! any (strcmp (method, {"nearest", "reference", "linear"})))
    error ("lafortune:badOption",
           "merl_eval: METHOD must be \"nearest\", \"reference\" or \"linear\"");
  endif
  if (strcmp (method, "nearest"))
    data = brdf.data;
    if (! isa (data, "double"))
      data = double (data);
    endif
    ## (a built oct-file that does not load warns there, once)
    [done, rgb, valid] = __lafortune_oct_call__ ("__merl_nearest__", "merl_eval", data,
                                                 brdf.valid, wi, wo);
    if (done)
      return;
    endif
    warning ("off", "backtrace", "local");
    if (exist ("__merl_nearest__", "file") != 3 && ! warned_once ())
      warning ("lafortune:noOctFile",
               "merl_eval: the oct-file __merl_nearest__ is missing (run make -C src, or pkg install the package); using the slower \"reference\" arithmetic");
    endif
    method = "reference";
  endif
  n = rows (wi);
  rgb = zeros (n, 3);
  valid = false (n, 1);
  above = wi(:,3) > 0 & wo(:,3) > 0;
  all_above = all (above);
  if (! all_above)
    if (! any (above))
      return;
    endif
    wi = wi(above,:);
    wo = wo(above,:);
  endif
  if (strcmp (method, "reference"))
    idx = merl_index_ref (wi, wo);
    v = brdf.data(idx,:);
    ok = brdf.valid(idx);
    if (! all (ok))
      v(! ok,:) = 0;
    endif
  else
    [th, td, pd] = merl_angles (wi, wo);
    ch = sqrt (max (th, 0) / (pi/2)) * 90;
    cd = td / (pi/2) * 90;
    cp = pd / pi * 180;
    ch = min (max (ch, 0), 89);
    cd = min (max (cd, 0), 89);
    cp = min (max (cp, 0), 180);
    h0 = min (floor (ch), 88); fh = ch - h0;
    d0 = min (floor (cd), 88); fd = cd - d0;
    p0 = min (floor (cp), 179); fp = cp - p0;
    p1 = mod (p0 + 1, 180);
    v = zeros (numel (ch), 3);
    wsum = zeros (numel (ch), 1);
    for a = 0:1
      wa = (1 - a) * (1 - fh) + a * fh;
      for b = 0:1
        wb = (1 - b) * (1 - fd) + b * fd;
        for c = 0:1
          wc = (1 - c) * (1 - fp) + c * fp;
          if (c == 0)
            pp = p0;
          else
            pp = p1;
          endif
          idx = ((h0 + a) * 90 + d0 + b) * 180 + pp + 1;
          w = wa .* wb .* wc .* brdf.valid(idx);
          v += w .* brdf.data(idx,:);
          wsum += w;
        endfor
      endfor
    endfor
    ok = wsum > 0;
    v = v ./ max (wsum, realmin);
    v(! ok,:) = 0;
  endif
  if (all_above)
    rgb = double (v);
    valid = ok;
  else
    rgb(above,:) = v;
    valid(above) = ok;
  endif
endfunction

## True after the first call (the missing oct-file is reported once).
function w = warned_once ()
  persistent done = false;
  w = done;
  done = true;
endfunction

%!function b = __synth ()
%!  b = merl_synth (@(wi, wo) [(wi(:,3) + wo(:,3)) / 2, wi(:,3) .* wo(:,3), sqrt(wi(:,3) .* wo(:,3))]);
%!endfunction

%!test
%! ## a reference-reader lookup at a bin's own grid point gives that bin
%! b2.valid = true (1458000, 1);
%! b2.data = repmat ((1:1458000)', 1, 3);
%! b2.valid = true (1458000, 1);
%! ih = 40; id = 20; ip = 33;
%! th = (ih / 90) ^ 2 * pi / 2 + 1e-9; td = id / 90 * pi / 2 + 1e-9; pd = ip / 180 * pi + 1e-9;
%! d = [sin(td)*cos(pd) sin(td)*sin(pd) cos(td)];
%! R = [cos(th) 0 sin(th); 0 1 0; -sin(th) 0 cos(th)];  # rotation about y by theta_h
%! wi = (R * d')'; wo = (R * [-d(1:2) d(3)]')';
%! assert (merl_eval (b2, wi, wo), ((ih * 90 + id) * 180 + ip + 1) * [1 1 1]);
%! ## rotating both about z (phi_h) changes nothing: isotropy
%! Rz = [cos(1) -sin(1) 0; sin(1) cos(1) 0; 0 0 1];
%! assert (merl_eval (b2, (Rz * wi')', (Rz * wo')'), ((ih * 90 + id) * 180 + ip + 1) * [1 1 1]);
%! ## reciprocity: swapping wi and wo folds phi_d into the same bin
%! assert (merl_eval (b2, wo, wi), merl_eval (b2, wi, wo));

%!test
%! ## bins of the reference reader (MERL's C lookup, compiled here) for
%! ## in-plane directions at whole degrees, built as it builds them from
%! ## angles (phi_out = pi on the far side): on bin edges and at the mirror
%! ## direction rounding decides, and the bin must still be the reader's
%! b2.valid = true (1458000, 1);
%! b2.data = repmat ((1:1458000)', 1, 3);
%! ref = [30 -80 771301; 30 -30 5491; 30 -29 102600; 30 10 682021; 0 0 1; 45 -45 8191; 45 20 876961];
%! ti = ref(:,1) * pi / 180; to = abs (ref(:,2)) * pi / 180; fo = pi * (ref(:,2) < 0);
%! wi = [sin(ti) .* cos(0), sin(ti) .* sin(0), cos(ti)];
%! wo = [sin(to) .* cos(fo), sin(to) .* sin(fo), cos(to)];
%! assert (merl_eval (b2, wi, wo)(:,1), ref(:,3));
%! ## merl_plane builds its table that way
%! S = merl_plane (b2, "theta_i", 30);
%! assert (S.rgb(S.theta_o == -30, 1), 5491);
%! assert (S.rgb(S.theta_o == -29, 1), 102600);

%!test
%! ## "nearest" (compiled) gives the bins of the reader's arithmetic
%! ## ("reference"), bit for bit: random pairs, in-plane pairs at whole and
%! ## half degrees (bin edges, mirror and retro directions), the same rotated
%! ## about z, wi = wo, wo within 1e-9 to 1e-3 of wi, h along the normal
%! b2.data = repmat ((1:1458000)', 1, 3);
%! b2.valid = true (1458000, 1);
%! rand ("state", 11);
%! n = 20000;
%! u = rand (n, 2); v = rand (n, 2);
%! wi = [sqrt(1 - u(:,1).^2) .* cos(2*pi*u(:,2)), sqrt(1 - u(:,1).^2) .* sin(2*pi*u(:,2)), u(:,1)];
%! wo = [sqrt(1 - v(:,1).^2) .* cos(2*pi*v(:,2)), sqrt(1 - v(:,1).^2) .* sin(2*pi*v(:,2)), v(:,1)];
%! [a1, a2] = ndgrid (-89.5:0.5:89.5);
%! ti = abs (a1(:)) * pi / 180; fi = pi * (a1(:) < 0);
%! to = abs (a2(:)) * pi / 180; fo = pi * (a2(:) < 0);
%! pi_ = [sin(ti).*cos(fi), sin(ti).*sin(fi), cos(ti)];
%! po = [sin(to).*cos(fo), sin(to).*sin(fo), cos(to)];
%! Rz = [cos(0.3) -sin(0.3) 0; sin(0.3) cos(0.3) 0; 0 0 1];
%! w = wi(1:2000,:);
%! p = randn (2000, 3); p -= sum (p .* w, 2) .* w; p ./= sqrt (sum (p .^ 2, 2));
%! e = 10 .^ -(3 + mod ((1:2000)', 7));
%! w2 = w + e .* p; w2 ./= sqrt (sum (w2 .^ 2, 2));
%! g = [sin(0.2) 0 cos(0.2)];
%! WI = [wi; pi_; pi_ * Rz'; w; w; g; -g(1) 0 g(3)];
%! WO = [wo; po; po * Rz'; w; w2; g .* [-1 1 1]; g];
%! [v1, ok1] = merl_eval (b2, WI, WO);
%! [v2, ok2] = merl_eval (b2, WI, WO, "reference");
%! assert (isequal (v1, v2));
%! assert (isequal (ok1, ok2));
%! assert (nnz (ok1) > 100000);

%!test
%! ## smooth function: nearest and linear agree with the function to bin accuracy
%! b = __synth ();
%! t = linspace (0.05, 1.3, 50)';
%! wi = [sin(t) 0*t cos(t)];
%! wo = [zeros(50,1) sin(0.4)*ones(50,1) cos(0.4)*ones(50,1)];
%! ex = [(wi(:,3) + wo(:,3)) / 2, wi(:,3) .* wo(:,3), sqrt(wi(:,3) .* wo(:,3))];
%! assert (merl_eval (b, wi, wo), ex, 0.05);
%! [v, ok] = merl_eval (b, wi, wo, "linear");
%! assert (all (ok));
%! assert (v, ex, 0.02);

%!test
%! ## below the horizon gives 0, invalid samples give 0 and valid = false
%! b = __synth ();
%! [v, ok] = merl_eval (b, [0 0 1; 0 0 1], [0 0.6 -0.8; 0 0 1]);
%! assert (v(1,:), [0 0 0]);
%! assert (ok', [false true]);
%! b3 = b; b3.valid(:) = false;
%! [v, ok] = merl_eval (b3, [0 0 1], [0 0 1]);
%! assert (v, [0 0 0]); assert (ok, false);
%! [v, ok] = merl_eval (b3, [0 0 1], [0 0 1], "linear");
%! assert (v, [0 0 0]); assert (ok, false);
%! [v, ok] = merl_eval (b3, [0 0 1; 0 0 -1], [0 0 1; 0 0 1], "reference");
%! assert (v, zeros (2, 3)); assert (ok, [false; false]);
%! [v, ok] = merl_eval (b, [0 0 1; 0 0 -1], [0 0 1; 0 0 1], "reference");
%! assert (v(2,:), [0 0 0]); assert (ok, [true; false]);
%! assert (v(1,:), merl_eval (b, [0 0 1], [0 0 1]));

%!error <Invalid call> merl_eval (1)
%!error id=lafortune:badMerl merl_eval (struct ("x", 1), [0 0 1], [0 0 1])
%!error id=lafortune:badOption merl_eval (struct ("data", zeros (1458000, 3), "valid", true (1458000, 1)), [0 0 1], [0 0 1], "cubic")
%!error id=lafortune:notUnit merl_eval (struct ("data", zeros (1458000, 3), "valid", true (1458000, 1)), [0 0 1.5], [0 0 1])
%!error id=lafortune:badDirections merl_eval (struct ("data", zeros (1458000, 3), "valid", true (1458000, 1)), [0 0 1 0], [0 0 1])
%!error id=lafortune:badMerl merl_eval (struct ("data", zeros (10, 3), "valid", true (10, 1)), [0 0 1], [0 0 1])
