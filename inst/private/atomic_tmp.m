## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{tmp} =} atomic_tmp (@var{file}, @var{fname})
## Name of a fresh temporary file in the folder of @var{file} (private), for
## write-then-rename.  The temporary name keeps @var{file}'s extension.  Errors
## with @code{lafortune:unwritable} when the folder does not exist or is not
## writable.  Commit with @code{atomic_commit (tmp, file)}.
## @end deftypefn
function tmp = atomic_tmp (file, fname)
  if (! ischar (file) || isempty (file) || rows (file) != 1)
    error ("lafortune:badFile", "%s: FILE must be a non-empty string", fname);
  endif
  [d, b, e] = fileparts (file);
  if (isempty (d))
    d = ".";
  endif
  if (! isfolder (d))
    error ("lafortune:unwritable", "%s: cannot write '%s': folder '%s' does not exist",
           fname, file, d);
  endif
  if (isfolder (file))
    error ("lafortune:unwritable", "%s: cannot write '%s': it is a folder", fname, file);
  endif
  tmp = fullfile (d, sprintf (".%s.tmp%d%06d%s", b, getpid (), randi (999999), e));
  [fid, msg] = fopen (tmp, "w");
  if (fid < 0)
    error ("lafortune:unwritable", "%s: cannot write in folder '%s': %s", fname, d, msg);
  endif
  fclose (fid);
endfunction
