// `postproc lsp` driven by the protocol library the extension's client is built on
// (vscode-languageserver-protocol), as the extension drives it: start, open a post, wait for its
// diagnostics, ask for completion, hover and a definition, shut down.
import { strict as assert } from 'node:assert';
import * as cp from 'node:child_process';
import * as path from 'node:path';
import { test } from 'node:test';
import {
  CompletionRequest, createProtocolConnection, DefinitionRequest, DidOpenTextDocumentNotification, ExitNotification,
  HoverRequest, InitializeRequest, PublishDiagnosticsNotification, PublishDiagnosticsParams, ShutdownRequest,
  StreamMessageReader, StreamMessageWriter,
} from 'vscode-languageserver-protocol/node';
import { postproc } from '../support';

test('a session as the extension runs it', async () => {
  const server = cp.spawn(postproc(), ['lsp'], { stdio: ['pipe', 'pipe', 'inherit'] });
  const connection = createProtocolConnection(new StreamMessageReader(server.stdout), new StreamMessageWriter(server.stdin));
  const diagnostics = new Promise<PublishDiagnosticsParams>((resolve) =>
    connection.onNotification(PublishDiagnosticsNotification.type, resolve));
  connection.listen();
  const init = await connection.sendRequest(InitializeRequest.type, {
    processId: process.pid, rootUri: null, capabilities: {}, workspaceFolders: null,
  });
  assert.equal(init.capabilities.hoverProvider, true);
  const uri = 'file://' + path.resolve('/tmp/postproc-vscode-test/post.gpp');
  const text = '@init_post\n  global numeric depth_left\nendp\n@line\n  depth_left = blknun\n  call @helper\nendp\n@helper\nendp\n';
  await connection.sendNotification(DidOpenTextDocumentNotification.type, {
    textDocument: { uri, languageId: 'gppl', version: 1, text },
  });
  const published = await diagnostics;
  assert.equal(published.uri, uri);
  assert.deepEqual(published.diagnostics.map((d) => [d.range.start.line, d.range.start.character, d.code, d.message]), [
    [4, 15, 383, "Variable 'blknun' is not defined: did you mean 'blknum'?"],
  ]);
  const completion = await connection.sendRequest(CompletionRequest.type, {
    textDocument: { uri }, position: { line: 4, character: 5 },
  });
  const labels = (Array.isArray(completion) ? completion : completion!.items).map((i) => i.label);
  assert.equal(labels[0], 'depth_left');
  const hover = await connection.sendRequest(HoverRequest.type, { textDocument: { uri }, position: { line: 4, character: 4 } });
  assert.match(JSON.stringify(hover!.contents), /numeric depth_left/);
  const definition = await connection.sendRequest(DefinitionRequest.type, {
    textDocument: { uri }, position: { line: 5, character: 9 },
  });
  assert.deepEqual(definition, { uri, range: { start: { line: 7, character: 0 }, end: { line: 7, character: 7 } } });
  await connection.sendRequest(ShutdownRequest.type);
  const exited = new Promise<number | null>((resolve) => server.on('exit', resolve));
  await connection.sendNotification(ExitNotification.type);
  assert.equal(await exited, 0);
  connection.dispose();
});
