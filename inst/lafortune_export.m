## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {} lafortune_export (@var{model}, @var{file}, @var{format})
## Write a Lafortune model to a file.
##
## @var{model} is a struct with fields @code{rho_d} (1 x 3), @code{Cxy},
## @code{Cz}, @code{e} (nlobes x 3) and optionally @code{name}, written as
## one line (control characters become spaces; "lafortune-model" when there
## is none).
## @var{format} is one of
##
## @table @code
## @item "json"
## the parameters as JSON (@code{jsonencode}): format tag, name, nlobes,
## rho_d, Cxy, Cz, e (lobes in rows, R, G, B in columns) and, under
## @code{exact}, the same values as IEEE-754 hex strings so that
## @code{lafortune_import} gives back the very same doubles.
## @item "text"
## a readable table in the paper's layout: rows rho_d and, per lobe, o_xy,
## o_z and n (the exponent); columns R, G, B.
## @item "brdfexplorer"
## an analytic @file{.brdf} file for Disney's BRDF Explorer: every
## parameter is a slider, the shader evaluates the same model: 0 below the
## horizon, and ux vx + uy vy as dot(L,V) - dot(L,N) dot(V,N), free of the
## tangents X and Y (which BRDF Explorer's lit sphere leaves undefined where
## the normal is +-Y).
## @item "merl"
## the model resampled into a MERL @file{.binary} (see @code{merl_synth},
## @code{merl_write}).
## @end table
##
## The output goes to a temporary file in the same folder, which is then
## renamed: a failed or interrupted export leaves any earlier @var{file}
## untouched and no half file.
##
## @example
## @group
## m = struct ("name", "demo", "rho_d", [0.1 0.05 0.02], "Cxy", [-1 -1 -1], ...
##             "Cz", [0.9 0.9 0.9], "e", [30 30 30]);
## lafortune_export (m, "demo.json", "json");
## lafortune_export (m, "demo.txt", "text");
## type demo.txt
## @end group
## @end example
## @seealso{lafortune_import, lafortune_fit, merl_write}
## @end deftypefn
function lafortune_export (model, file, format)
  if (nargin != 3)
    print_usage ();
  endif
  name = "lafortune-model";
  if (isstruct (model) && isfield (model, "name") && ischar (model.name) && ! isempty (model.name))
    ## one line of printable text: a control character (a newline) would end
    ## the comment it is written in, and BRDF Explorer refuses such a file
    name = model.name(:).';
    name(name < 32 | name == 127) = " ";
    name = strtrim (name);
    if (isempty (name))
      name = "lafortune-model";
    endif
  endif
  model = check_model (model, "lafortune_export");
  formats = {"json", "text", "brdfexplorer", "merl"};
  if (! ischar (format) || ! any (strcmpi (format, formats)))
    error ("lafortune:badFormat", "lafortune_export: unknown FORMAT '%s'; expected one of %s",
           arg_str (format), strjoin (formats, ", "));
  endif
  format = lower (format);
  if (strcmp (format, "merl"))
    merl_write (file, merl_synth (model, "name", name));
    return;
  endif
  switch (format)
    case "json"
      txt = json_text (model, name);
    case "text"
      txt = table_text (model, name);
    case "brdfexplorer"
      txt = brdf_text (model, name);
  endswitch
  atomic_write (file, "lafortune_export", @(fid) write_text (fid, txt));
endfunction

function txt = json_text (m, name)
  hex = @(v) cellstr (num2hex (v(:)))';
  s = struct ("format", "lafortune-model", "version", 1, "name", name,
              "nlobes", rows (m.Cxy),
              "formula", "f = rho_d/pi + sum_k max(Cxy_k*(ux*vx + uy*vy) + Cz_k*uz*vz, 0)^e_k, per channel R, G, B",
              "rho_d", m.rho_d, "Cxy", {m.Cxy}, "Cz", {m.Cz}, "e", {m.e},
              "exact", struct ("rho_d", {hex(m.rho_d)}, "Cxy", {hex(m.Cxy')},
                               "Cz", {hex(m.Cz')}, "e", {hex(m.e')}));
  txt = [jsonencode(s) "\n"];
endfunction

function txt = table_text (m, name)
  n = rows (m.Cxy);
  txt = sprintf ("# Lafortune model: %s, %d lobe(s), one column per channel\n", name, n);
  txt = [txt "# f = rho_d/pi + sum_k max(o_xy,k (ux vx + uy vy) + o_z,k uz vz, 0)^n_k\n"];
  txt = [txt sprintf("%-14s %14s %14s %14s\n", "parameter", "R", "G", "B")];
  txt = [txt sprintf("%-14s %14.6g %14.6g %14.6g\n", "rho_d", m.rho_d)];
  for k = 1:n
    txt = [txt sprintf("%-14s %14.6g %14.6g %14.6g\n", sprintf ("lobe %d o_xy", k), m.Cxy(k,:))];
    txt = [txt sprintf("%-14s %14.6g %14.6g %14.6g\n", sprintf ("lobe %d o_z", k), m.Cz(k,:))];
    txt = [txt sprintf("%-14s %14.6g %14.6g %14.6g\n", sprintf ("lobe %d n", k), m.e(k,:))];
  endfor
endfunction

function txt = brdf_text (m, name)
  n = rows (m.Cxy);
  ch = "rgb";
  par = "";
  par = [par slider("rho_d_r", 0, 1, m.rho_d(1)) slider("rho_d_g", 0, 1, m.rho_d(2)) ...
         slider("rho_d_b", 0, 1, m.rho_d(3))];
  body = "    vec3 f = vec3(rho_d_r, rho_d_g, rho_d_b) / PI;\n";
  for k = 1:n
    for c = 1:3
      par = [par slider(sprintf("Cxy%d_%s", k, ch(c)), -2, 2, m.Cxy(k,c))];
      par = [par slider(sprintf("Cz%d_%s", k, ch(c)), -2, 2, m.Cz(k,c))];
      par = [par slider(sprintf("e%d_%s", k, ch(c)), 0, 100, m.e(k,c))];
    endfor
    body = [body sprintf(["    f += vec3(lobe(Cxy%d_r, Cz%d_r, e%d_r, sxy, sz),\n" ...
                          "              lobe(Cxy%d_g, Cz%d_g, e%d_g, sxy, sz),\n" ...
                          "              lobe(Cxy%d_b, Cz%d_b, e%d_b, sxy, sz));\n"], ...
                         k, k, k, k, k, k, k, k, k)];
  endfor
  txt = ["analytic\n\n" ...
         sprintf("# Lafortune model '%s', %d lobe(s), exported by lafortune_export\n", name, n) ...
         "# f = rho_d/pi + sum_k max(Cxy_k (ux vx + uy vy) + Cz_k uz vz, 0)^e_k per channel\n\n" ...
         "::begin parameters\n" par "::end parameters\n\n" ...
         "::begin shader\n\n" ...
         "const float PI = 3.14159265358979323846;\n\n" ...
         "float lobe(float cxy, float cz, float e, float sxy, float sz)\n{\n" ...
         "    float b = cxy * sxy + cz * sz;\n" ...
         "    return b > 0.0 ? pow(b, e) : 0.0;\n}\n\n" ...
         "vec3 BRDF( vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y )\n{\n" ...
         "    float ln = dot(L, N);\n" ...
         "    float vn = dot(V, N);\n" ...
         "    if (ln <= 0.0 || vn <= 0.0) return vec3(0.0);   // below the horizon, as lafortune_eval\n" ...
         "    // ux vx + uy vy without X and Y (BRDF Explorer's lit sphere has NaN there at N = +-Y)\n" ...
         "    float sxy = dot(L, V) - ln * vn;\n" ...
         "    float sz = ln * vn;\n" ...
         body ...
         "    return f;\n}\n\n" ...
         "::end shader\n"];
endfunction

function s = slider (nm, lo, hi, v)
  lo = min (lo, floor (v));
  hi = max (hi, ceil (2 * v));
  s = sprintf ("float %s %.9g %.9g %.17g\n", nm, lo, hi, v);
endfunction

%!shared m, d
%! m = struct ("name", "test model", "rho_d", [0.1 0.05 pi/100], "Cxy", [-1 -1.1 -0.9; 0.3 0.4 0.5], ...
%!             "Cz", [0.9 0.95 0.85; 0.3 0.2 0.1], "e", [30.123456789 40 1234.5; 2 3 4]);
%! d = tempname (); mkdir (d);

%!test
%! f = fullfile (d, "m.json");
%! lafortune_export (m, f, "json");
%! r = lafortune_import (f);
%! assert (r.name, "test model");
%! for fld = {"rho_d", "Cxy", "Cz", "e"}
%!   assert (isequal (r.(fld{1}), m.(fld{1})));   # bit for bit
%! endfor

%!test
%! f = fullfile (d, "m.txt");
%! lafortune_export (m, f, "text");
%! t = fileread (f);
%! assert (! isempty (strfind (t, "lobe 2 o_xy")));
%! assert (! isempty (regexp (t, "rho_d\\s+0.1\\s+0.05\\s+0.0314159")));
%! assert (! isempty (regexp (t, "lobe 1 n\\s+30.1235\\s+40\\s+1234.5")));

%!test
%! f = fullfile (d, "m.brdf");
%! lafortune_export (m, f, "brdfexplorer");
%! t = fileread (f);
%! assert (strncmp (t, "analytic", 8));
%! assert (! isempty (strfind (t, "::begin parameters")));
%! assert (! isempty (strfind (t, "vec3 BRDF( vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y )")));
%! assert (! isempty (regexp (t, "float e1_b 0 2469 1234.5")));
%! assert (numel (regexp (t, "\\nfloat \\w+ [-0-9]")), 3 + 2 * 9);
%! ## below the horizon 0, as lafortune_eval; ux vx + uy vy free of X and Y
%! assert (! isempty (strfind (t, "if (ln <= 0.0 || vn <= 0.0) return vec3(0.0);")));
%! assert (! isempty (strfind (t, "float sxy = dot(L, V) - ln * vn;")));
%! assert (isempty (regexp (t, "dot\\([LV], [XY]\\)", "once")));
%! assert (! isempty (strfind (t, "Lafortune model 'test model'")));

%!test
%! ## the shader's formula, evaluated here, is lafortune_eval's (1e-12),
%! ## for pairs above and below the horizon and a single pair
%! t = [0.2 0.7 1.2 1.5]; p = [0 0.5 2 3];
%! [T, P] = ndgrid (t, p);
%! L = [sin(T(:)) .* cos(P(:)) sin(T(:)) .* sin(P(:)) cos(T(:))];
%! V = L([3 1 4 2 8 5 6 7 10 9 12 11 14 13 16 15],:);
%! V(end,:) = [0 sin(2) cos(2)];                     # one below the horizon
%! ln = L(:,3); vn = V(:,3);
%! sxy = sum (L .* V, 2) - ln .* vn; sz = ln .* vn;
%! g = repmat (m.rho_d / pi, rows (L), 1);
%! for k = 1:2
%!   g += max (m.Cxy(k,:) .* sxy + m.Cz(k,:) .* sz, 0) .^ m.e(k,:);
%! endfor
%! g(ln <= 0 | vn <= 0,:) = 0;
%! assert (g, lafortune_eval (m, L, V), 1e-12);
%! assert (lafortune_eval (m, L(1,:), V(end,:)), [0 0 0]);

%!test
%! ## control characters leave the name; a model without a name says so
%! f = fullfile (d, "n.brdf");
%! m2 = m; m2.name = sprintf ("red\nplastic\t(2 lobes)\r");
%! lafortune_export (m2, f, "brdfexplorer");
%! t = fileread (f);
%! assert (! isempty (strfind (t, "Lafortune model 'red plastic (2 lobes)'")));
%! assert (! any (t < 32 & t != 10));
%! lafortune_export (m2, fullfile (d, "n.txt"), "text");
%! t = fileread (fullfile (d, "n.txt"));
%! assert (strncmp (t, "# Lafortune model: red plastic (2 lobes), 2 lobe(s)", 50));
%! lafortune_export (rmfield (m, "name"), f, "brdfexplorer");
%! assert (! isempty (strfind (fileread (f), "Lafortune model 'lafortune-model'")));

%!test
%! f = fullfile (d, "m.binary");
%! lafortune_export (m, f, "merl");
%! b = merl_read (f);
%! wi = [sind(30) 0 cosd(30)]; wo = [-sind(20) 0 cosd(20)];
%! assert (merl_eval (b, wi, wo), lafortune_eval (m, wi, wo), -0.05);

%!test
%! ## an export whose write fails (a file size limit of 0 makes the disk
%! ## refuse) keeps the earlier file and leaves no temporary
%! f = fullfile (d, "keep.json");
%! lafortune_export (m, f, "json");
%! before = fileread (f);
%! scr = fullfile (d, "w.m");
%! fid = fopen (scr, "w");
%! fprintf (fid, "addpath ('%s');\n", fileparts (which ("lafortune_export")));
%! fprintf (fid, "m = struct ('rho_d', [1 1 1], 'Cxy', [1 1 1], 'Cz', [1 1 1], 'e', [2 2 2]);\n");
%! fprintf (fid, "try\n lafortune_export (m, '%s', 'json');\n exit (3);\ncatch err\n disp (err.identifier);\nend_try_catch\n", f);
%! fclose (fid);
%! [st, out] = system (sprintf ("bash -c \"trap '' XFSZ; ulimit -f 0; octave-cli --no-gui --norc --no-history '%s'\" 2>&1", scr));
%! assert (st == 0, "%s", out);
%! assert (! isempty (strfind (out, "lafortune:unwritable")), out);
%! assert (fileread (f), before);
%! unlink (scr);
%! assert (isempty (dir (fullfile (d, ".keep*"))));

%!error <Invalid call> lafortune_export (m, "x.json")
%!error <unknown FORMAT 'yaml'> lafortune_export (m, "x.yaml", "yaml")
%!error id=lafortune:badFormat lafortune_export (m, "x.json", 3)
%!error id=lafortune:unwritable lafortune_export (m, "/nonexistent-dir/x.json", "json")
%!error id=lafortune:badModel lafortune_export (struct ("rho_d", 1), "x.json", "json")

%!test
%! assert (strncmp (d, tempdir (), numel (tempdir ())));   # only our scratch folder
%! confirm_recursive_rmdir (false, "local");
%! rmdir (d, "s");
