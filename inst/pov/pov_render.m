## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{img} =} pov_render (@var{scene}, @var{material})
## @deftypefnx {lafortune} {[@var{img}, @var{info}] =} pov_render (@var{scene}, @var{material}, @var{name}, @var{value}, @dots{})
## @deftypefnx {lafortune} {[@var{imgs}, @var{infos}] =} pov_render (@var{scene}, @{@var{m1}, @var{m2}, @dots{}@}, @dots{})
## Render @var{scene} with @var{material} in POV-Ray.
##
## Writes the scene with @code{pov_write_scene} into a new temporary folder,
## runs @command{povray} there (@code{+I +O +W +H +FE -D}, OpenEXR output,
## @code{File_Gamma=1.0}, statistics on, output captured) and reads the
## image back with @code{exrread}: @var{img} is @var{H} x @var{W} x 3 linear
## radiance (POV-Ray writes half floats: about 3 significant digits).  The
## folder is removed afterwards.
##
## Options (others go to @code{pov_write_scene}: @qcode{"entries"},
## @qcode{"knots"}, @qcode{"table_tol"}, @qcode{"lobe_tol"}, @qcode{"crop"},
## @qcode{"cull"}, @qcode{"pad"}, @qcode{"dense"}, @qcode{"lights"}):
## @table @asis
## @item @qcode{"antialias"} (0)
## false or 0: one ray through each pixel centre (what @code{rt_render}
## does with @code{scene.jitter} false and @code{scene.spp} = 1; use this to
## compare the two without sampling noise).  @var{n} >= 2: POV-Ray's
## anti-aliasing @code{+A0.0 +AM1 +R@var{n}}, which supersamples every pixel
## that differs at all from its neighbours with a regular @var{n} x @var{n}
## grid of rays (the samples of @code{rt_render} with @code{scene.jitter}
## false and @code{scene.spp} = @var{n}^2) and averages them together with
## the first ray through the pixel centre: a pixel is (c + @var{n}^2
## g)/(@var{n}^2 + 1), c the centre sample and g the grid's mean (test_pov
## checks it against rt_render's samples).  Against jittered samples the images agree up to
## sampling noise.
## @item @qcode{"jitter"} (false)
## With anti-aliasing, jitter the subsamples (@code{+J}).
## @item @qcode{"threads"} (0)
## Render threads (@code{+WT}); 0 leaves POV-Ray's default (all cores).
## @item @qcode{"keep"} (@qcode{""})
## File name to copy the generated @file{.pov} scene to (with several
## lights, their include files go beside it).
## @item @qcode{"povray"} (@qcode{"povray"})
## The POV-Ray program.
## @end table
##
## A scene with several lights or an environment light
## (@code{pov_write_scene}'s animation, one frame per light) is rendered
## frame by frame in up to 32 POV-Ray processes at once (POV-Ray idles
## between frames; each process then has one render thread unless
## @qcode{"threads"} says otherwise), and the frames are added up.
## Several materials (a cell array) are rendered in the same scene at once:
## their scenes are written one after the other, and their POV-Ray runs go
## to up to 32 processes at once, each with one render thread unless
## @qcode{"threads"} says otherwise; @var{imgs} and @var{infos} are cell
## arrays, each image the one a call of its own gives.
## A run that POV-Ray gives up because its render threads did not start in
## its time limit (a loaded machine) is tried again, at most 3 times.
## @var{info} has the fields of @code{pov_write_scene}'s info (@code{bytes},
## @code{terms}, @code{entries}, @dots{}) and @code{time} (seconds, the
## @command{povray} run), @code{parse_time}, @code{trace_time} (POV-Ray's
## own statistics, NaN when absent), @code{write_time} (writing the scene),
## @code{command} and @code{output} (what POV-Ray printed).
##
## Errors: @code{lafortune:povNotFound} when the program cannot be found,
## @code{lafortune:povFailed} (with POV-Ray's message) when it fails, e.g.
## on a parse error.
##
## @example
## @group
## scene = scene_make ("sphere");
## m = struct ("rho_d", [0.1 0.1 0.1], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [30 30 30]);
## [img, info] = pov_render (scene, m);
## ref = rt_render (scene, m, "jitter", false);
## img_psnr (ref, img)
## @end group
## @end example
## @seealso{pov_write_scene, rt_render, img_psnr, exrread}
## @end deftypefn
function [img, info] = pov_render (scene, material, varargin)
  if (nargin < 2)
    print_usage ();
  endif
  fname = "pov_render";
  mine = {"antialias", "jitter", "threads", "keep", "povray"};
  own = {};
  pass = {};
  if (mod (numel (varargin), 2) != 0)
    error ("lafortune:badOption", "%s: options must be NAME, VALUE pairs", fname);
  endif
  for k = 1:2:numel (varargin)
    if (ischar (varargin{k}) && any (strcmpi (varargin{k}, mine)))
      own(end+1:end+2) = varargin(k:k+1);
    else
      pass(end+1:end+2) = varargin(k:k+1);
    endif
  endfor
  opt = __lafortune_parse_opts__ (own, fname, struct ("antialias", 0, "jitter", false, "threads", 0,
                                        "keep", "", "povray", "povray"));
  aa = opt.antialias;
  if (islogical (aa) && isscalar (aa) && ! aa)
    aa = 0;                               # "antialias", false: one ray per pixel centre
  endif
  if (! isscalar (aa) || ! isnumeric (aa) || aa != fix (aa) || aa < 0 || aa == 1 || aa > 9)
    error ("lafortune:badOption", "%s: \"antialias\" must be false, 0 or an integer from 2 to 9", fname);
  endif
  th = opt.threads;
  if (! isscalar (th) || ! isnumeric (th) || th != fix (th) || th < 0)
    error ("lafortune:badOption", "%s: \"threads\" must be an integer >= 0", fname);
  endif
  if (! ischar (opt.keep) || ! ischar (opt.povray) || isempty (opt.povray))
    error ("lafortune:badOption", "%s: \"keep\" and \"povray\" must be strings", fname);
  endif
  exe = find_povray (opt.povray, fname);
  several = iscell (material);
  if (! several)
    material = {material};
  elseif (isempty (material))
    error ("lafortune:badOption", "%s: MATERIAL must be a material or a non-empty cell array of them",
           fname);
  elseif (! isempty (opt.keep))
    error ("lafortune:badOption", "%s: \"keep\" takes one material, got %d",
           fname, numel (material));
  endif
  nm = numel (material);

  d = tempname ();
  [ok, msg] = mkdir (d);
  if (! ok)
    error ("lafortune:unwritable", "%s: cannot make the folder '%s': %s", fname, d, msg);
  endif
  unwind_protect
    ## every material's scene, each in a folder of its own, and the POV-Ray
    ## runs they need: one, or one per group of its lights' frames
    base = "scene";
    if (! isempty (opt.keep))                 # its lights' files are named after it
      [~, base] = fileparts (opt.keep);
      base = regexprep (base, "[^A-Za-z0-9_.-]", "_");
    endif
    common = sprintf ("+I%s.pov +Oimage.exr +FE +W%d +H%d -D +GS -GR -GP File_Gamma=1.0",
                      base, scene.width, scene.height);
    if (aa)
      common = [common, sprintf(" +A0.0 +AM1 +R%d", aa)];
      if (opt.jitter)
        common = [common, " +J1.0"];
      else
        common = [common, " -J"];
      endif
    else
      common = [common, " -A"];
    endif
    M = struct ("dir", cell (1, nm), "info", [], "wtime", 0, "K", 0, "args", "");
    jobs = struct ("m", {}, "args", {});
    for i = 1:nm
      M(i).dir = d;
      if (several)
        M(i).dir = fullfile (d, sprintf ("m%d", i));
        mkdir (M(i).dir);
      endif
      t0 = tic ();
      M(i).info = pov_write_scene (scene, material{i}, fullfile (M(i).dir, [base ".pov"]), pass{:});
      M(i).wtime = toc (t0);
      args = common;
      K = 0;
      if (isfield (M(i).info, "frames"))      # lights: frame k is light k
        K = M(i).info.frames;
        args = [args, sprintf(" +KFI1 +KFF%d", K)];
      endif
      M(i).K = K;
      ## POV-Ray idles between frames and before a render (its front end
      ## polls), so the frames of many lights, and the scenes of several
      ## materials, go to several processes at once, each with one render
      ## thread unless "threads" says otherwise
      tj = th;
      if ((K > 1 || several) && ! tj)
        tj = 1;
      endif
      if (tj)
        args = [args, sprintf(" +WT%d", tj)];
      endif
      M(i).args = args;
      if (K > 1)
        e = round (linspace (0, K, min (K, 32) + 1));
        for j = 1:numel (e) - 1
          jobs(end+1) = struct ("m", i, "args", sprintf ("%s +SF%d +EF%d", args, e(j) + 1, e(j+1)));
        endfor
      else
        jobs(end+1) = struct ("m", i, "args", args);
      endif
    endfor
    cmd = run_jobs (exe, jobs, M, d);
    img = cell (1, nm);
    info = cell (1, nm);
    for i = 1:nm
      J = find ([jobs.m] == i);
      st = 0;
      out = "";
      t = [Inf -Inf];
      for j = J
        sj = str2double (fileread_or (fullfile (M(i).dir, sprintf ("status%d.txt", j)), "1"));
        oj = fileread_or (fullfile (M(i).dir, sprintf ("log%d.txt", j)), "");
        tj = str2double (strsplit (strtrim (fileread_or (fullfile (M(i).dir, sprintf ("time%d.txt", j)), "NaN NaN"))));
        if (numel (tj) == 2)
          t = [min(t(1), tj(1)), max(t(2), tj(2))];
        endif
        if (sj != 0 && st == 0)
          st = sj;
          out = [oj, out];
        else
          out = [out, oj];
        endif
      endfor
      K = M(i).K;
      if (K)
        exr = arrayfun (@(k) fullfile (M(i).dir, sprintf ("image%0*d.exr", numel (num2str (K)), k)),
                        1:K, "UniformOutput", false);
      else
        exr = {fullfile(M(i).dir, "image.exr")};
      endif
      if (st != 0 || ! all (cellfun (@(f) exist (f, "file") == 2, exr)))
        error ("lafortune:povFailed", "%s: POV-Ray failed (exit status %d): %s", fname, st,
               pov_message (out));
      endif
      im = 0;
      for k = 1:numel (exr)                   # the lights' frames sum to the image
        x = exrread (exr{k});
        im += double (x(:,:,1:3));
      endfor
      img{i} = im;
      in = M(i).info;
      in.file = opt.keep;
      in.write_time = M(i).wtime;
      in.time = t(2) - t(1);
      in.parse_time = stat_time (out, "Parse Time");
      in.trace_time = stat_time (out, "Trace Time");
      in.command = sprintf ("cd %s && %s %s", shell_quote (M(i).dir), shell_quote (exe), M(i).args);
      in.output = out;
      info{i} = in;
    endfor
    if (! isempty (opt.keep))
      pov = fullfile (d, [base ".pov"]);
      __lafortune_write__ (opt.keep, fname, "file", @(tmp) copyfile (pov, tmp, "f"));
      if (M(1).K)                             # the lights' files, beside it
        kd = fileparts (opt.keep);
        for k = 1:M(1).K
          inc = M(1).info.includes{k};
          __lafortune_write__ (fullfile (kd, inc), fname, "file",
                               @(tmp) copyfile (fullfile (d, inc), tmp, "f"));
        endfor
      endif
    endif
  unwind_protect_cleanup
    confirm_recursive_rmdir (false, "local");
    rmdir (d, "s");
  end_unwind_protect
  if (! several)
    img = img{1};
    info = info{1};
  endif
endfunction

## Run the POV-Ray JOBS (job j in its material's folder, its output in
## logJ.txt, its exit status in statusJ.txt, its start and end times in
## timeJ.txt), at most 32 at once.  POV-Ray gives up when its render
## threads do not start within its own time limit, which a loaded machine
## can exceed: that run is tried again (at most 3 times); any other failure
## is left to the caller at once.  Returns the shell command
function cmd = run_jobs (exe, jobs, M, d)
  lines = {"set +m"};
  for j = 1:numel (jobs)
    dir = M(jobs(j).m).dir;
    log = sprintf ("log%d.txt", j);
    lines{end+1} = sprintf (["(cd %s && t0=$(date +%%s.%%N); for a in 1 2 3; do %s %s > %s 2>&1; s=$?; ", ...
                             "if [ $s -ne 0 ] && grep -q 'waiting for worker thread startup' %s; ", ...
                             "then continue; fi; break; done; echo $s > status%d.txt; ", ...
                             "echo \"$t0 $(date +%%s.%%N)\" > time%d.txt) &"],
                            shell_quote (dir), shell_quote (exe), jobs(j).args, log, log, j, j);
    lines{end+1} = "while [ $(jobs -rp | wc -l) -ge 32 ]; do wait -n; done";
  endfor
  lines{end+1} = "wait";
  script = fullfile (d, "run.sh");
  fid = fopen (script, "w");
  fprintf (fid, "%s\n", lines{:});
  fclose (fid);
  cmd = sprintf ("bash %s", shell_quote (script));
  system (cmd);
endfunction

function s = fileread_or (f, dflt)
  s = dflt;
  if (exist (f, "file"))
    s = fileread (f);
  endif
endfunction

function exe = find_povray (p, fname)
  if (any (p == "/"))
    ok = exist (p, "file") == 2;
    exe = p;
  else
    [st, out] = system (sprintf ("command -v %s 2>/dev/null", shell_quote (p)));
    ok = st == 0 && ! isempty (strtrim (out));
    exe = strtrim (out);
  endif
  if (! ok)
    error ("lafortune:povNotFound",
           "%s: POV-Ray program '%s' not found; install POV-Ray 3.7 (Debian: apt-get install povray) or pass \"povray\", PATH",
           fname, p);
  endif
endfunction

function s = shell_quote (s)
  s = ["'", strrep(s, "'", "'\\''"), "'"];
endfunction

## what POV-Ray said after its banner, long lines rejoined
function msg = pov_message (out)
  lines = strsplit (strrep (out, "\r", "\n"), "\n");
  h = find (strncmp (lines, "==== [", 6), 1);
  if (isempty (h))
    h = 0;
  endif
  lines = lines(h+1:end);
  drop = strncmp (lines, "==== [", 6) | strncmp (lines, "Rendered ", 9) ...
         | ! cellfun (@isempty, regexp (lines, "configuration file", "once")) ...
         | cellfun (@isempty, strtrim (lines));
  lines = lines(! drop);
  msg = "";
  for k = 1:numel (lines)
    if (k > 1 && lines{k}(1) == " ")
      msg = [msg, " ", strtrim(lines{k})];        # POV-Ray wraps at 80 columns
    else
      msg = [msg, "\n", strtrim(lines{k})];
    endif
  endfor
  msg = strtrim (msg);
  if (numel (msg) > 2000)
    msg = [msg(1:2000), " ..."];
  endif
  if (isempty (msg))
    msg = "(no message)";
  endif
endfunction

function t = stat_time (out, what)
  tok = regexp (out, [what, ':[^(]*\(([0-9.]+) seconds\)'], "tokens", "once");
  if (isempty (tok))
    t = NaN;
  else
    t = str2double (tok{1});
  endif
endfunction

%!demo
%! scene = scene_make ("spheres");
%! m = struct ("rho_d", [0.05 0.15 0.1], "Cxy", [-1 -1 -1], "Cz", [0.95 0.95 0.95],
%!             "e", [60 60 60]);
%! [img, info] = pov_render (scene, m);
%! ref = rt_render (scene, m, "jitter", false);
%! printf ("POV-Ray %.2f s, %d bytes, PSNR %.1f dB against rt_render\n",
%!         info.time, info.bytes, img_psnr (ref, img));
%! subplot (1, 3, 1); imshow (min (ref / max (ref(:)), 1)); title ("rt\\_render");
%! subplot (1, 3, 2); imshow (min (img / max (ref(:)), 1)); title ("pov\\_render");
%! subplot (1, 3, 3); imshow (img_diff (ref, img)); title ("difference");

%!shared sc, m
%! sc.name = "t"; sc.width = 16; sc.height = 12; sc.spp = 1; sc.seed = 1; sc.background = [0 0 0];
%! sc.camera = struct ("type", "orthographic", "eye", [0 0 5], "target", [0 0 0], "up", [0 1 0],
%!                     "extent", 2.5, "fov", []);
%! sc.light = struct ("type", "directional", "direction", [0 0.6 0.8], "position", [],
%!                    "irradiance", 2);
%! sc.objects = struct ("type", "sphere", "center", [0.3 0 0], "radius", 1, "point", [],
%!                      "normal", [], "vertices", [], "faces", [], "normals", []);
%! m = struct ("rho_d", [0.1 0.2 0.3], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [30 30 30]);

%!test
%! [img, info] = pov_render (sc, m, "entries", 32);
%! assert (size (img), [12 16 3]);
%! assert (img(1,1,:), zeros (1, 1, 3));          # background
%! assert (all (img(6,9,:) > 0));                 # sphere, shifted right
%! assert (info.time > 0 && info.bytes > 0 && info.entries > 0);
%! assert (isfinite (info.parse_time) && isfinite (info.trace_time));
%! ## the brightest pixel: where N is halfway between L and V
%! [~, i] = max (img(:,:,1)(:));
%! [r, c] = ind2sub ([12 16], i);
%! assert (r < 6.5);                              # above the centre (light from above)
