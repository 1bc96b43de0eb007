1;
## fclcert's bridge to the Octave fuzzy-logic-toolkit: the JSON-lines protocol of docs/iut-protocol.md on
## stdin/stdout, one request per line. load: the FIS text (fclcert presents programs as FIS) written to a
## file in the process's private temporary directory and read by readfis; eval: evalfis. Whatever the
## toolkit prints (its puts before an error) is captured by evalc, so stdout carries replies only.

function s = q (text)
  ## a JSON string
  s = jsonencode (char (text));
endfunction

function s = num (v)
  if (isnan (v))
    s = "NaN";
  elseif (isinf (v))
    if (v > 0) s = "Infinity"; else s = "-Infinity"; endif
  else
    s = sprintf ("%.17g", v);
  endif
endfunction

function reply (body, id)
  if (isempty (id))
    printf ("{%s}\n", body);
  else
    printf ("{%s,\"id\":%s}\n", body, num (id));
  endif
  fflush (stdout);
endfunction

function fail (kind, message, id)
  reply (sprintf ("\"ok\":false,\"error\":{\"kind\":%s,\"message\":%s}", q (kind), q (message)), id);
endfunction

function m = message_of (err, printed)
  ## the error's message, else what the toolkit printed
  m = strtrim (err.message);
  if (isempty (m))
    m = strtrim (printed);
  endif
endfunction

pkg load fuzzy-logic-toolkit
toolkit = pkg ("list", "fuzzy-logic-toolkit");
version = sprintf ("%s (Octave %s)", toolkit{1}.version, OCTAVE_VERSION);
fis = [];
x = [];
file = [tempname() ".fis"];

while (true)
  ## input, not fgetl (stdin): Octave's streams read a pipe in whole buffers and would wait for the next request
  try
    line = input ("", "s");
  catch
    break;    # end of input
  end_try_catch
  if (isempty (strtrim (line)))
    continue;
  endif
  id = [];
  try
    request = jsondecode (line);
    if (isfield (request, "id"))
      id = request.id;
    endif
    op = request.op;
  catch err
    fail ("error", ["not a request: " err.message], id);
    continue;
  end_try_catch
  switch (op)
    case "hello"
      reply (sprintf ("\"ok\":true,\"implementation\":{\"name\":\"Octave fuzzy-logic-toolkit\",\"version\":%s,\"claims\":[]}", q (version)), id);
    case "load"
      fis = [];
      fid = fopen (file, "w");
      fputs (fid, request.fcl);
      fclose (fid);
      printed = "";
      try
        printed = evalc ("loaded = readfis (file);");
        fis = loaded;
        x = zeros (1, columns (fis.input));
        reply (sprintf ("\"ok\":true,\"blocks\":[%s]", q (fis.name)), id);
      catch err
        fail ("rejected", message_of (err, printed), id);
      end_try_catch
      delete (file);
    case "eval"
      if (isempty (fis))
        fail ("error", "no program is loaded", id);
        continue;
      endif
      names = {};
      if (isstruct (request.inputs))
        names = fieldnames (request.inputs);
      endif
      unknown = "";
      for k = 1 : numel (names)
        j = find (strcmpi (names{k}, arrayfun (@(v) v.name, fis.input, "UniformOutput", false)), 1);
        if (isempty (j))
          unknown = names{k};
          break;
        endif
        x(j) = request.inputs.(names{k});
        ## evalfis refuses an input outside its Range, which has no other effect on its value: widen it
        fis.input(j).range = [min(fis.input(j).range(1), x(j)), max(fis.input(j).range(2), x(j))];
      endfor
      if (! isempty (unknown))
        fail ("error", [unknown " is not an input of " fis.name], id);
        continue;
      endif
      printed = "";
      try
        printed = evalc ("y = evalfis (x, fis);");
        body = "\"ok\":true,\"outputs\":{";
        for k = 1 : columns (fis.output)
          if (k > 1)
            body = [body ","];
          endif
          body = [body q(fis.output(k).name) ":" num(y(k))];
        endfor
        reply ([body "}"], id);
      catch err
        fail ("error", message_of (err, printed), id);
      end_try_catch
    case "reset"
      if (isempty (fis))
        fail ("error", "no program is loaded", id);
      else
        x = zeros (1, columns (fis.input));
        reply ("\"ok\":true", id);
      endif
    case "export"
      reply ("\"ok\":false,\"error\":{\"kind\":\"unsupported\"}", id);
    case "bye"
      reply ("\"ok\":true", id);
      break;
    otherwise
      fail ("error", ["unknown op " op], id);
  endswitch
endwhile
