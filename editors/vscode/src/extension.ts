// The GPPL extension: starts `postproc lsp` for posts and machine files, and adds two commands.
// - Post with...: runs the post on a job the user picks, writes the NC beside the post, opens it.
// - Explain NC line: from a line of that NC program, opens the GPP line that wrote it (and says which
//   toolpath command it came from); from a GPP line, lists the NC lines it wrote.
import * as cp from 'child_process';
import * as fs from 'fs';
import * as path from 'path';
import * as vscode from 'vscode';
import { LanguageClient, LanguageClientOptions, ServerOptions } from 'vscode-languageclient/node';
import { ExplainedLine, gppPath, parseExplain } from './explain';

let client: LanguageClient | undefined;

// The last run of "Post with...": what explains its NC lines.
interface PostRun {
  post: string;
  machine?: string;
  job: string;
  nc: string;
  lines: ExplainedLine[];
}
let lastRun: PostRun | undefined;

function executable(): string {
  return vscode.workspace.getConfiguration('postproc').get<string>('path', 'postproc');
}

// The machine file beside a post, as `postproc lsp` and `postproc check` take it.
function machineFileOf(post: string): string | undefined {
  const stem = post.slice(0, post.length - path.extname(post).length);
  return ['.prp', '.PRP', '.vmid', '.VMID', '.mac', '.MAC'].map((e) => stem + e).find((f) => fs.existsSync(f));
}

function run(args: string[], cwd: string): Promise<{ code: number; out: string; err: string }> {
  return new Promise((resolve) => {
    cp.execFile(executable(), args, { cwd, maxBuffer: 512 * 1024 * 1024 }, (error, out, err) => {
      const code = error && typeof (error as NodeJS.ErrnoException).code === 'number' ? Number((error as NodeJS.ErrnoException).code) : error ? 1 : 0;
      resolve({ code, out: out.toString(), err: err.toString() });
    });
  });
}

async function postWith(): Promise<void> {
  const editor = vscode.window.activeTextEditor;
  if (!editor || editor.document.languageId !== 'gppl') {
    vscode.window.showErrorMessage('Post with...: open a post (.gpp) first.');
    return;
  }
  await editor.document.save();
  const post = editor.document.uri.fsPath;
  const picked = await vscode.window.showOpenDialog({
    canSelectMany: false,
    openLabel: 'Post this job',
    filters: { 'Toolpath (trace)': ['trace', 'txt'], 'All files': ['*'] },
  });
  if (!picked || picked.length === 0) return;
  const job = picked[0].fsPath;
  const machine = machineFileOf(post);
  const nc = path.join(path.dirname(post), path.basename(job, path.extname(job)) + '.nc');
  const common = ['--post', post, ...(machine ? ['--prp', machine] : []), '-q'];
  const posted = await run(['run', ...common, '-o', nc, job], path.dirname(post));
  if (posted.code !== 0) {
    vscode.window.showErrorMessage(`postproc run failed: ${posted.err.trim().split('\n')[0]}`);
    return;
  }
  const explained = await run(['explain', ...common, job], path.dirname(post));
  lastRun = { post, machine, job, nc, lines: explained.code === 0 ? parseExplain(explained.out) : [] };
  await vscode.commands.executeCommand('setContext', 'postproc.hasExplained', true);
  await vscode.window.showTextDocument(vscode.Uri.file(nc), { viewColumn: vscode.ViewColumn.Beside });
}

async function explainLine(): Promise<void> {
  const editor = vscode.window.activeTextEditor;
  if (!editor || !lastRun) {
    vscode.window.showErrorMessage('Explain NC line: post a job with "Post with..." first.');
    return;
  }
  const here = editor.document.uri.fsPath;
  const line = editor.selection.active.line + 1;
  const post = lastRun.post;
  if (here === post || lastRun.lines.some((l) => gppPath(post, l.gppFile) === here)) {  // a GPP line: the NC lines it wrote
    const written = lastRun.lines.filter((l) => l.gppLine === line && gppPath(post, l.gppFile) === here);
    if (written.length === 0) {
      vscode.window.showInformationMessage(`Line ${line} of ${path.basename(here)} wrote nothing in ${path.basename(lastRun.nc)}.`);
      return;
    }
    const pick = await vscode.window.showQuickPick(
      written.map((l) => ({ label: `${l.ncFile}:${l.ncLine}`, description: l.text, line: l })),
      { placeHolder: `${written.length} NC line(s) written by line ${line}` });
    if (!pick) return;
    const nc = path.join(path.dirname(lastRun.nc), pick.line.ncFile === path.basename(lastRun.nc) ? path.basename(lastRun.nc) : pick.line.ncFile);
    const doc = await vscode.window.showTextDocument(vscode.Uri.file(nc), { viewColumn: vscode.ViewColumn.Beside });
    const at = new vscode.Position(pick.line.ncLine - 1, 0);
    doc.selection = new vscode.Selection(at, at);
    doc.revealRange(new vscode.Range(at, at), vscode.TextEditorRevealType.InCenter);
    return;
  }
  const ncName = path.basename(here);
  const found = lastRun.lines.find((l) => l.ncLine === line && (l.ncFile === ncName || here === lastRun!.nc));
  if (!found) {
    vscode.window.showInformationMessage(`No explanation for line ${line} of ${ncName}: post again with "Post with...".`);
    return;
  }
  const gpp = gppPath(lastRun.post, found.gppFile);
  const doc = await vscode.window.showTextDocument(vscode.Uri.file(gpp), { viewColumn: vscode.ViewColumn.Beside });
  const at = new vscode.Position(found.gppLine - 1, 0);
  doc.selection = new vscode.Selection(at, at);
  doc.revealRange(new vscode.Range(at, at), vscode.TextEditorRevealType.InCenter);
  vscode.window.setStatusBarMessage(`${ncName}:${line} came from toolpath command ${found.command} through ${found.procedure}`, 10000);
}

export function activate(context: vscode.ExtensionContext): void {
  const serverOptions: ServerOptions = { command: executable(), args: ['lsp'] };
  const clientOptions: LanguageClientOptions = {
    documentSelector: [
      { scheme: 'file', language: 'gppl' },
      { scheme: 'file', language: 'prp' },
      { scheme: 'file', pattern: '**/*.{vmid,VMID}' },
    ],
  };
  client = new LanguageClient('postproc', 'postproc lsp', serverOptions, clientOptions);
  void client.start();
  context.subscriptions.push(
    vscode.commands.registerCommand('postproc.postWith', postWith),
    vscode.commands.registerCommand('postproc.explainLine', explainLine),
  );
}

export function deactivate(): Thenable<void> | undefined {
  return client?.stop();
}
