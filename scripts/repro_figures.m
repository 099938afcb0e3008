## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} repro_figures ()
## Step 6 of `make reproduce`: the figures, PNG through gnuplot
## (print -dpngcairo) into RESULTS/figures:
## plane-MATERIAL.png (the paper's Fig. 2 and 3: in-plane data at
## theta_i = 30 degrees and the 1-, 2-, 3-lobe fits, per channel),
## renders-MATERIAL.png (Fig. 4 and 5: measured render and the 1/2/3-lobe
## renders with their difference images and PSNR), fit-trace.png (fit error
## against run time) and spp.png (render PSNR against run time).
## @end deftypefn
function repro_figures ()
  c = repro_config ();
  warning ("off", "Octave:gnuplot-graphics");
  graphics_toolkit ("gnuplot");
  fd = fullfile (c.results, "figures");
  if (! isfolder (fd))
    mkdir (fd);
  endif
  chn = {"red", "green", "blue"};
  for i = 1:numel (c.materials)
    mat = c.materials{i};
    printf ("reproduce: [%s] figures\n", mat);
    fflush (stdout);
    b = merl_read (fullfile (c.results, "data", [mat ".binary"]));
    S = merl_plane (b, "theta_i", 30, "max_angle", c.max_angle, "step", 0.5);
    ## Fig. 2 / 3
    h = figure ("visible", "off", "position", [0 0 1200 380]);
    for ch = 1:3
      subplot (1, 3, ch);
      semilogy (S.theta_o, S.rgb(:,ch), "k.", "markersize", 4);
      hold on;
      for k = c.lobes
        m = lafortune_import (fullfile (c.results, "fit", sprintf ("%s-inplane-%d.json", mat, k)));
        semilogy (S.theta_o, lafortune_eval (m, S.wi, S.wo)(:,ch), "linewidth", 1.5);
      endfor
      hold off;
      xlabel ("theta_o (degrees); the mirror direction is at -30", "interpreter", "none");
      if (ch == 1)
        ttl = sprintf ("%s: %s, theta_i = 30", mat, chn{ch});
      else
        ttl = sprintf ("%s channel", chn{ch});
      endif
      title (ttl, "interpreter", "none");
      legend ([{"data"}, arrayfun(@(k) sprintf ("%d lobe(s)", k), c.lobes, "uniformoutput", false)],
              "location", "northeast");
    endfor
    save_png (h, fullfile (fd, ["plane-" mat ".png"]));
    ## Fig. 4 / 5
    rd = fullfile (c.results, "render");
    ref = exrread (fullfile (rd, [mat "-measured.exr"]));
    fits = jsondecode (fileread (fullfile (rd, [mat "-fits.json"])));
    [rgb, stops] = img_tonemap (ref, "auto");
    h = figure ("visible", "off", "position", [0 0 300 * (1 + numel (c.lobes)) 560]);
    subplot (1, 1 + numel (c.lobes), 1);
    show (rgb, "measured (rt_render)");
    dscale = 0.1 * max (ref(:));
    for k = c.lobes
      img = exrread (fullfile (rd, sprintf ("%s-inplane-%d.exr", mat, k)));
      im = img_tonemap (img, stops);
      d = uint8 (255 * img_diff (ref, img, "scale", dscale));
      ## the difference image as an inset, a third of the size, bottom right
      hs = floor (rows (im) / 3); ws = floor (columns (im) / 3);
      r = round (linspace (1, rows (d), hs)); q = round (linspace (1, columns (d), ws));
      im(end-hs+1:end, end-ws+1:end, :) = d(r, q, :);
      subplot (1, 1 + numel (c.lobes), 1 + k);
      show (im, sprintf ("%d lobe(s): %.2f dB", k, fits.inplane(k).psnr_pov));
    endfor
    save_png (h, fullfile (fd, ["renders-" mat ".png"]));
  endfor
  ## fit error against run time
  h = figure ("visible", "off", "position", [0 0 1000 400]);
  for i = 1:numel (c.materials)
    mat = c.materials{i};
    F = jsondecode (fileread (fullfile (c.results, "fit", [mat ".json"])));
    subplot (1, numel (c.materials), i);
    for ch = 1:3
      T = [F.inplane.trace(ch).time(:), F.inplane.trace(ch).rmse(:)];
      loglog (max (T(:,1), 1e-3), T(:,2), "linewidth", 1.5);
      hold on;
    endfor
    hold off;
    xlabel ("elapsed time (s)"); ylabel ("rmse of the best fit so far");
    title (sprintf ("%s: in-plane fit, 1 to %d lobes", mat, max (c.lobes)), "interpreter", "none");
    legend (chn, "location", "northeast");
  endfor
  save_png (h, fullfile (fd, "fit-trace.png"));
  ## render PSNR against run time
  h = figure ("visible", "off", "position", [0 0 700 420]);
  for i = 1:numel (c.materials)
    mat = c.materials{i};
    P = jsondecode (fileread (fullfile (c.results, "spp", [mat ".json"])));
    semilogx (P.time, P.psnr, "-o", "linewidth", 1.5);
    hold on;
    for j = 1:numel (P.spp)
      text (P.time(j), P.psnr(j) + 0.6, sprintf ("%d", P.spp(j)));
    endfor
  endfor
  hold off;
  xlabel ("render time (s)"); ylabel (sprintf ("PSNR against %d spp (dB)", c.spp));
  title ("measured data, rt_render: PSNR against run time (labels: samples per pixel)", "interpreter", "none");
  legend (c.materials, "location", "southeast");
  save_png (h, fullfile (fd, "spp.png"));
endfunction

function show (rgb, ttl)
  image (rgb);
  axis image;
  set (gca, "xtick", [], "ytick", []);
  title (ttl, "interpreter", "none");
endfunction

function save_png (h, file)
  tmp = [file ".tmp.png"];
  print (h, "-dpngcairo", "-r90", tmp);
  close (h);
  [err, msg] = rename (tmp, file);
  if (err)
    error ("lafortune:unwritable", "repro_figures: cannot write '%s': %s", file, msg);
  endif
endfunction
