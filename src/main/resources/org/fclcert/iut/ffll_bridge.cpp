// fclcert's bridge to FFLL 2.2.1: speaks fclcert's JSON-lines protocol (docs/iut-protocol.md) on stdin/stdout
// and drives FFLL through its C API (FFLLAPI.h). fclcert compiles it with g++ against the FFLL library it is
// given (org.fclcert.iut.FfllIut) and starts it as a process of its own, so a crash of FFLL ends only this
// process. Written for fclcert; no FFLL code is copied here.
//
// What it observes (docs/iut-protocol.md, "FFLL"): FFLL reads a file, so each program is written to a private
// temporary file; inputs are set by their index in FFLL's model (names from FFLL's own model, through
// FuzzyModelBase, matched without regard to letter case); the one output is read with ffll_get_output_value
// (FLT_MIN when no rule fired). export is FFLL's own writer, FuzzyModelBase::save_to_fcl_file.
#include <cerrno>
#include <cfloat>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <cwchar>
#include <cwctype>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>
#include "FFLLAPI.h"
#include "FuzzyModelBase.h"
#include "FuzzyVariableBase.h"

namespace {

// ---- a small JSON reader: enough for fclcert's requests ------------------------------------------------
struct Json {
    enum Type { NUL, BOOL, NUM, STR, ARR, OBJ } type = NUL;
    bool b = false;
    double n = 0;
    std::string s;
    std::vector<Json> items;
    std::vector<std::pair<std::string, Json>> members;
    const Json* get(const std::string& key) const {
        for (const auto& m : members) if (m.first == key) return &m.second;
        return nullptr;
    }
};

struct Parser {
    const std::string& t;
    size_t i = 0;
    explicit Parser(const std::string& text) : t(text) {}
    void ws() { while (i < t.size() && (t[i] == ' ' || t[i] == '\t' || t[i] == '\r' || t[i] == '\n')) i++; }
    bool lit(const char* w) {
        size_t k = strlen(w);
        if (t.compare(i, k, w) == 0) { i += k; return true; }
        return false;
    }
    static void utf8(std::string& out, unsigned long cp) {
        if (cp < 0x80) out += (char) cp;
        else if (cp < 0x800) { out += (char) (0xC0 | (cp >> 6)); out += (char) (0x80 | (cp & 0x3F)); }
        else if (cp < 0x10000) { out += (char) (0xE0 | (cp >> 12)); out += (char) (0x80 | ((cp >> 6) & 0x3F)); out += (char) (0x80 | (cp & 0x3F)); }
        else { out += (char) (0xF0 | (cp >> 18)); out += (char) (0x80 | ((cp >> 12) & 0x3F)); out += (char) (0x80 | ((cp >> 6) & 0x3F)); out += (char) (0x80 | (cp & 0x3F)); }
    }
    bool hex4(unsigned long& v) {
        if (i + 4 > t.size()) return false;
        v = 0;
        for (int k = 0; k < 4; k++) {
            char c = t[i++];
            v <<= 4;
            if (c >= '0' && c <= '9') v |= c - '0';
            else if (c >= 'a' && c <= 'f') v |= c - 'a' + 10;
            else if (c >= 'A' && c <= 'F') v |= c - 'A' + 10;
            else return false;
        }
        return true;
    }
    bool str(std::string& out) {
        if (i >= t.size() || t[i] != '"') return false;
        i++;
        while (i < t.size()) {
            char c = t[i++];
            if (c == '"') return true;
            if (c != '\\') { out += c; continue; }
            if (i >= t.size()) return false;
            char e = t[i++];
            switch (e) {
                case 'n': out += '\n'; break;
                case 't': out += '\t'; break;
                case 'r': out += '\r'; break;
                case 'b': out += '\b'; break;
                case 'f': out += '\f'; break;
                case 'u': {
                    unsigned long cp;
                    if (!hex4(cp)) return false;
                    if (cp >= 0xD800 && cp < 0xDC00 && t.compare(i, 2, "\\u") == 0) {
                        size_t back = i;
                        i += 2;
                        unsigned long lo;
                        if (hex4(lo) && lo >= 0xDC00 && lo < 0xE000) cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
                        else i = back;
                    }
                    utf8(out, cp);
                    break;
                }
                default: out += e;
            }
        }
        return false;
    }
    bool value(Json& v) {
        ws();
        if (i >= t.size()) return false;
        char c = t[i];
        if (c == '{') {
            v.type = Json::OBJ; i++; ws();
            if (i < t.size() && t[i] == '}') { i++; return true; }
            while (true) {
                ws();
                std::string key;
                if (!str(key)) return false;
                ws();
                if (i >= t.size() || t[i] != ':') return false;
                i++;
                Json m;
                if (!value(m)) return false;
                v.members.emplace_back(key, m);
                ws();
                if (i < t.size() && t[i] == ',') { i++; continue; }
                if (i < t.size() && t[i] == '}') { i++; return true; }
                return false;
            }
        }
        if (c == '[') {
            v.type = Json::ARR; i++; ws();
            if (i < t.size() && t[i] == ']') { i++; return true; }
            while (true) {
                Json m;
                if (!value(m)) return false;
                v.items.push_back(m);
                ws();
                if (i < t.size() && t[i] == ',') { i++; continue; }
                if (i < t.size() && t[i] == ']') { i++; return true; }
                return false;
            }
        }
        if (c == '"') { v.type = Json::STR; return str(v.s); }
        if (lit("true")) { v.type = Json::BOOL; v.b = true; return true; }
        if (lit("false")) { v.type = Json::BOOL; return true; }
        if (lit("null")) { v.type = Json::NUL; return true; }
        const char* start = t.c_str() + i;
        char* end = nullptr;
        v.n = strtod(start, &end);
        if (end == start) return false;
        v.type = Json::NUM;
        i += end - start;
        return true;
    }
};

std::string quote(const std::string& s) {
    std::string out = "\"";
    for (unsigned char c : s) {
        if (c == '"') out += "\\\"";
        else if (c == '\\') out += "\\\\";
        else if (c == '\n') out += "\\n";
        else if (c == '\r') out += "\\r";
        else if (c == '\t') out += "\\t";
        else if (c < 0x20) { char buf[8]; snprintf(buf, sizeof buf, "\\u%04x", c); out += buf; }
        else out += (char) c;
    }
    return out + "\"";
}

std::string number(double v) {
    if (v != v) return "NaN";
    if (v > DBL_MAX) return "Infinity";
    if (v < -DBL_MAX) return "-Infinity";
    char buf[40];
    snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string lower(std::string s) {
    for (auto& c : s) c = (char) tolower((unsigned char) c);
    return s;
}

std::string narrow(const wchar_t* w) {
    std::string out;
    if (w == nullptr) return out;
    for (; *w; w++) Parser::utf8(out, (unsigned long) *w);
    return out;
}

// FuzzyModelBase keeps get_var protected; a subclass of the bridge's own makes it visible (nothing overridden).
// As the most derived class it must construct FFLL's virtual base itself: a model has no parent.
struct ModelView : public FuzzyModelBase {
    ModelView() : FFLLBase(this) { init(); }
    using FuzzyModelBase::get_var;
};

// ---- the session ---------------------------------------------------------------------------------------
std::string version = "2.2.1";
std::string dir;            // private temporary directory
int model = -1;             // the C API's model of the loaded program, -1 when none
int child = -1;
std::string blockName;
std::vector<std::string> inputs;   // FFLL's input variables, in its index order
std::string outputName;
std::vector<double> values;        // the inputs as last set (0 after load and reset)
std::string programFile;

void reply(const std::string& body, const Json* id) {
    std::string line = "{" + body;
    if (id != nullptr && id->type == Json::NUM) line += ",\"id\":" + number(id->n);
    line += "}\n";
    fputs(line.c_str(), stdout);
    fflush(stdout);
}

void error(const std::string& kind, const std::string& message, const Json* id) {
    reply("\"ok\":false,\"error\":{\"kind\":" + quote(kind) + ",\"message\":" + quote(message) + "}", id);
}

std::string message(int m) {
    const char* text = ffll_get_msg_textA(m);
    return text == nullptr ? "" : std::string(text);
}

// FUNCTION_BLOCK's name as written (FFLL keeps no name of its own that the C API shows); empty when unnamed.
std::string writtenBlockName(const std::string& text) {
    std::string up = text;
    for (auto& c : up) c = (char) toupper((unsigned char) c);
    size_t at = 0;
    while ((at = up.find("FUNCTION_BLOCK", at)) != std::string::npos) {
        bool startOk = at == 0 || !(isalnum((unsigned char) up[at - 1]) || up[at - 1] == '_');
        size_t after = at + 14;
        if (startOk && (after >= up.size() || !(isalnum((unsigned char) up[after]) || up[after] == '_'))) {
            size_t k = after;
            while (k < text.size() && (text[k] == ' ' || text[k] == '\t')) k++;
            size_t s = k;
            while (k < text.size() && (isalnum((unsigned char) text[k]) || text[k] == '_')) k++;
            return text.substr(s, k - s);
        }
        at = after;
    }
    return "";
}

void unload() {
    if (model >= 0) ffll_close_model(model);
    model = -1;
    child = -1;
    inputs.clear();
    values.clear();
    outputName.clear();
    blockName.clear();
}

void load(const Json& req, const Json* id) {
    unload();
    const Json* fcl = req.get("fcl");
    if (fcl == nullptr || fcl->type != Json::STR) { error("rejected", "load without 'fcl'", id); return; }
    {
        std::ofstream out(programFile, std::ios::binary | std::ios::trunc);
        out << fcl->s;
    }
    int m = ffll_new_model();
    if (m < 0) { error("rejected", "ffll_new_model failed", id); return; }
    int result = ffll_load_fcl_file(m, programFile.c_str());
    if (result < 0) {
        std::string text = message(m);
        ffll_close_model(m);
        error("rejected", text.empty() ? "FFLL did not load the program (ffll_load_fcl_file returned "
                + std::to_string(result) + ", no message)" : "FFLL: " + text, id);
        return;
    }
    // FFLL's own view of the variables: the same file read into a FuzzyModelBase, which the C API does not show
    ModelView names;
    if (names.load_from_fcl_file(programFile.c_str()) < 0) {
        ffll_close_model(m);
        error("rejected", "FFLL loaded the program through its C API but not into a FuzzyModelBase", id);
        return;
    }
    int count = names.get_input_var_count();
    for (int k = 0; k < count; k++) {
        FuzzyVariableBase* v = names.get_var(k);
        inputs.push_back(v == nullptr ? "" : narrow(v->get_id()));
    }
    FuzzyVariableBase* out = names.get_var(OUTPUT_IDX);
    outputName = out == nullptr ? "output" : narrow(out->get_id());
    model = m;
    child = ffll_new_child(model);
    values.assign(inputs.size(), 0.0);
    blockName = writtenBlockName(fcl->s);
    std::string shown = blockName.empty() ? "function_block" : blockName;
    reply("\"ok\":true,\"blocks\":[" + quote(shown) + "]", id);
}

void eval(const Json& req, const Json* id) {
    if (model < 0) { error("error", "no program is loaded", id); return; }
    const Json* block = req.get("block");
    if (block != nullptr && block->type == Json::STR) {
        std::string shown = blockName.empty() ? "function_block" : blockName;
        if (lower(block->s) != lower(shown)) { error("error", "no function block " + block->s + " (FFLL holds one: " + shown + ")", id); return; }
    }
    const Json* given = req.get("inputs");
    if (given == nullptr || given->type != Json::OBJ) { error("error", "eval without 'inputs'", id); return; }
    for (const auto& m : given->members) {
        size_t k = 0;
        while (k < inputs.size() && lower(inputs[k]) != lower(m.first)) k++;
        if (k == inputs.size()) { error("error", m.first + " is not an input of the loaded program (FFLL's inputs are addressed by index)", id); return; }
        if (m.second.type != Json::NUM) { error("error", m.first + " is not a number", id); return; }
        values[k] = m.second.n;
    }
    for (size_t k = 0; k < values.size(); k++) ffll_set_value(model, child, (int) k, values[k]);
    double y = ffll_get_output_value(model, child);
    reply("\"ok\":true,\"outputs\":{" + quote(outputName) + ":" + number(y) + "}", id);
}

void reset(const Json* id) {
    if (model < 0) { error("error", "no program is loaded", id); return; }
    child = ffll_new_child(model);
    values.assign(inputs.size(), 0.0);
    reply("\"ok\":true", id);
}

void exportProgram(const Json* id) {
    if (model < 0) { error("error", "no program is loaded", id); return; }
    ModelView written;
    std::string file = dir + "/export.fcl";
    if (written.load_from_fcl_file(programFile.c_str()) < 0 || written.save_to_fcl_file(file.c_str()) < 0) {
        error("error", "FFLL could not write the program back", id);
        return;
    }
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    reply("\"ok\":true,\"fcl\":" + quote(text.str()), id);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1) version = argv[1];
    char pattern[] = "/tmp/fclcert-ffll-XXXXXX";
    const char* made = mkdtemp(pattern);
    if (made == nullptr) { fprintf(stderr, "ffll bridge: no temporary directory: %s\n", strerror(errno)); return 2; }
    dir = made;
    programFile = dir + "/program.fcl";
    std::string line;
    while (std::getline(std::cin, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        Json req;
        Parser p(line);
        if (!p.value(req) || req.type != Json::OBJ) { fprintf(stderr, "ffll bridge: not a JSON object: %.200s\n", line.c_str()); continue; }
        const Json* id = req.get("id");
        const Json* op = req.get("op");
        std::string o = op != nullptr && op->type == Json::STR ? op->s : "";
        if (o == "hello") reply("\"ok\":true,\"implementation\":{\"name\":\"FFLL\",\"version\":" + quote(version) + ",\"claims\":[]}", id);
        else if (o == "load") load(req, id);
        else if (o == "eval") eval(req, id);
        else if (o == "reset") reset(id);
        else if (o == "export") exportProgram(id);
        else if (o == "bye") { reply("\"ok\":true", id); break; }
        else error("error", "unknown op '" + o + "'", id);
    }
    unload();
    unlink(programFile.c_str());
    unlink((dir + "/export.fcl").c_str());
    rmdir(dir.c_str());
    return 0;
}
