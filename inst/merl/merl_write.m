## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {} merl_write (@var{file}, @var{brdf})
## Write a MERL material in the database's @file{.binary} format.
##
## @var{brdf} is a struct as @code{merl_read} or @code{merl_synth} return it
## (fields @code{data}, 1458000 x 3, and @code{valid}).  Values are divided
## by the channel scales (1/1500, 1.15/1500, 1.66/1500) and each stored value
## is chosen so that reading it back gives exactly the value written:
## read-write-read round-trips bit for bit (an arbitrary value that no
## stored double reproduces exactly comes back within an ulp or two).  The file is written to a
## temporary file in the same folder and renamed, so a failed write leaves any
## earlier @var{file} untouched and no half file.
##
## @example
## @group
## brdf = merl_synth (@@(wi, wo) ones (rows (wi), 3) / pi);   # white Lambertian
## merl_write ([tempname() ".binary"], brdf);
## @end group
## @end example
## @seealso{merl_read, merl_synth}
## @end deftypefn
function merl_write (file, brdf)
  if (nargin != 2)
    print_usage ();
  endif
  __lafortune_check_merl__ (brdf, "merl_write");
  data = double (brdf.data);
  if (! all (isfinite (data(:))))
    error ("lafortune:badPayload", "merl_write: BRDF.data must be finite");
  endif
  [dims, scale, n] = __lafortune_merl_consts__ ();
  stored = data ./ scale;
  ## make stored * scale reproduce data exactly (x/s*s can miss by an ulp)
  for c = 1:3
    s = stored(:,c);
    bad = find (s * scale(c) != data(:,c));
    for step = [1 -1 2 -2]
      if (isempty (bad))
        break;
      endif
      t = s(bad) + step * eps (s(bad));
      hit = t * scale(c) == data(bad,c);
      s(bad(hit)) = t(hit);
      bad = bad(! hit);
    endfor
    stored(:,c) = s;
  endfor
  __lafortune_write__ (file, "merl_write",
                       @(fid) 4 * fwrite (fid, dims, "int32") + 8 * fwrite (fid, stored(:), "float64"),
                       "ieee-le");
endfunction

%!test
%! d = tempname (); mkdir (d);
%! f = fullfile (d, "x.binary");
%! b = merl_synth (@(wi, wo) rand (rows (wi), 3) * 3.7, "missing", 80);
%! merl_write (f, b);
%! s = dir (f);
%! assert (s.bytes, 34992012);
%! r = merl_read (f);
%! assert (r.data, b.data, -4 * eps);
%! ## what was read writes back bit for bit
%! merl_write (f, r);
%! r1 = merl_read (f);
%! assert (isequal (r1.data, r.data));
%! ## a write that fails half-way (a file size limit makes the disk refuse)
%! ## leaves the old file as it was and no temporary behind
%! before = hash ("md5", fileread (f));
%! scr = fullfile (d, "w.m");
%! fid = fopen (scr, "w");
%! fprintf (fid, "addpath ('%s');\n", fileparts (which ("__lafortune_write__")));
%! fprintf (fid, "b = merl_synth (@(wi, wo) ones (rows (wi), 3));\n");
%! fprintf (fid, "try\n merl_write ('%s', b);\n exit (3);\ncatch err\n disp (err.identifier);\nend_try_catch\n", f);
%! fclose (fid);
%! [st, out] = system (sprintf ("bash -c \"trap '' XFSZ; ulimit -f 1000; octave-cli --no-gui --norc --no-history '%s'\" 2>&1", scr));
%! assert (st == 0, "%s", out);
%! assert (! isempty (strfind (out, "lafortune:unwritable")), out);
%! assert (hash ("md5", fileread (f)), before);
%! unlink (scr);
%! assert (numel (dir (d)), 3);   # ., .. and x.binary
%! assert (strncmp (d, tempdir (), numel (tempdir ())));   # only our scratch folder
%! confirm_recursive_rmdir (false, "local");
%! rmdir (d, "s");

%!error <Invalid call> merl_write ("x")
%!error id=lafortune:badMerl merl_write ("x.binary", struct ("data", 1))
%!error id=lafortune:unwritable merl_write ("/nonexistent-dir/x.binary", struct ("data", zeros (1458000, 3), "valid", true (1458000, 1)))
%!error id=lafortune:unwritable merl_write (tempdir, struct ("data", zeros (1458000, 3), "valid", true (1458000, 1)))
