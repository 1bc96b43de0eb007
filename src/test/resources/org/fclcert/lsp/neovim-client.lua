-- Drives fclcert's language server from Neovim's built-in LSP client (Neovim 0.7 and later) for NeovimLspTest:
-- attaches it to the current buffer, waits for the diagnostics, asks for a hover, a definition and a completion
-- list at the places the environment names, writes what Neovim holds as JSON to $FCL_OUT, and quits.
local out = os.getenv('FCL_OUT')
local result = {}
local ok, err = pcall(function()
  local cmd = vim.fn.json_decode(os.getenv('FCL_CMD'))
  local buf = vim.api.nvim_get_current_buf()
  local id = vim.lsp.start_client({
    name = 'fclcert',
    cmd = cmd,
    root_dir = vim.fn.getcwd(),
    init_options = { dialect = 'strict' },
  })
  vim.lsp.buf_attach_client(buf, id)
  result.attached = vim.wait(60000, function() return #vim.diagnostic.get(buf) > 0 end, 50)
  result.diagnostics = {}
  for _, d in ipairs(vim.diagnostic.get(buf)) do
    local lsp = (d.user_data or {}).lsp or {}
    table.insert(result.diagnostics, {
      lnum = d.lnum, col = d.col, end_col = d.end_col, severity = d.severity, message = d.message,
      code = d.code or lsp.code, source = d.source,
    })
  end
  local function at(name)
    local l, c = os.getenv(name):match('(%d+):(%d+)')
    return { textDocument = { uri = vim.uri_from_bufnr(buf) }, position = { line = tonumber(l), character = tonumber(c) } }
  end
  local function ask(method, place)
    local replies = vim.lsp.buf_request_sync(buf, method, at(place), 30000) or {}
    local reply = replies[id] or {}
    return reply.result
  end
  local hover = ask('textDocument/hover', 'FCL_HOVER')
  result.hover = hover and hover.contents and hover.contents.value
  local definition = ask('textDocument/definition', 'FCL_DEFINITION')
  if definition and definition[1] then
    result.definition = { line = definition[1].range.start.line, character = definition[1].range.start.character }
  end
  local completion = ask('textDocument/completion', 'FCL_COMPLETION')
  result.completion = {}
  for _, item in ipairs((completion and (completion.items or completion)) or {}) do
    table.insert(result.completion, item.label)
  end
  vim.lsp.stop_client(id)
  vim.wait(5000, function() return vim.lsp.get_client_by_id(id) == nil end, 50)
end)
if not ok then result.error = tostring(err) end
local f = io.open(out, 'w')
f:write(vim.fn.json_encode(result))
f:close()
vim.cmd('qa!')
