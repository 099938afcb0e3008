## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} repro_save (@var{file}, @var{value})
## Write @var{value} as JSON (a struct) or as text (a char) to @var{file}
## through a temporary file and a rename, so that an interrupted step leaves
## no half file for Make to take as done.
## @end deftypefn
function repro_save (file, value)
  d = fileparts (file);
  repro_mkdir (d);
  if (ischar (value))
    txt = value;
  else
    txt = jsonencode (value);
  endif
  tmp = [file ".tmp"];
  fid = fopen (tmp, "w");
  if (fid < 0)
    error ("lafortune:unwritable", "repro_save: cannot write '%s'", tmp);
  endif
  bad = fputs (fid, txt) != 0;
  bad |= fclose (fid) != 0;
  ## Octave's fputs and fclose do not report a disk that refuses the data
  if (bad || stat (tmp).size != numel (txt))
    unlink (tmp);
    error ("lafortune:unwritable", "repro_save: writing '%s' failed (disk full?)", tmp);
  endif
  [err, msg] = rename (tmp, file);
  if (err)
    error ("lafortune:unwritable", "repro_save: cannot rename onto '%s': %s", file, msg);
  endif
endfunction
