// A small strict JSON reader for the sidecar <asset>.smpl.json. Unity's
// JsonUtility cannot tell a missing key from a zero and needs [Serializable]
// mirror classes; this reader returns plain values instead:
//   object -> Dictionary<string, object>, array -> List<object>,
//   string -> string, number -> double, true/false -> bool, null -> null.
// Hostile input never crashes it: depth is limited and every error is one
// line naming the position.
using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace SmplExport.Correctives
{
    public static class MiniJson
    {
        const int MaxDepth = 64;

        /// <summary>Parses text; returns false and a one-line error on malformed input.</summary>
        public static bool TryParse(string text, out object value, out string error)
        {
            value = null;
            error = null;
            if (text == null)
            {
                error = "no text";
                return false;
            }
            var reader = new Reader(text);
            try
            {
                value = reader.ParseValue(0);
                reader.SkipSpace();
                if (reader.Pos != text.Length) throw reader.Fail("unexpected text after the value");
                return true;
            }
            catch (FormatException e)
            {
                value = null;
                error = e.Message;
                return false;
            }
        }

        // Exceptions stay inside this file: TryParse is the only entry point.
        sealed class Reader
        {
            readonly string s;
            public int Pos;

            public Reader(string text) { s = text; }

            public FormatException Fail(string what)
            {
                return new FormatException("JSON error at character " + Pos + ": " + what);
            }

            public void SkipSpace()
            {
                while (Pos < s.Length && (s[Pos] == ' ' || s[Pos] == '\t' || s[Pos] == '\n' || s[Pos] == '\r')) ++Pos;
            }

            public object ParseValue(int depth)
            {
                if (depth > MaxDepth) throw Fail("nesting deeper than " + MaxDepth);
                SkipSpace();
                if (Pos >= s.Length) throw Fail("unexpected end of text");
                char c = s[Pos];
                if (c == '{') return ParseObject(depth);
                if (c == '[') return ParseArray(depth);
                if (c == '"') return ParseString();
                if (c == 't') return Literal("true", true);
                if (c == 'f') return Literal("false", false);
                if (c == 'n') return Literal("null", null);
                return ParseNumber();
            }

            object Literal(string word, object result)
            {
                if (string.CompareOrdinal(s, Pos, word, 0, word.Length) != 0) throw Fail("unknown literal");
                Pos += word.Length;
                return result;
            }

            Dictionary<string, object> ParseObject(int depth)
            {
                var result = new Dictionary<string, object>();
                ++Pos;
                SkipSpace();
                if (Pos < s.Length && s[Pos] == '}') { ++Pos; return result; }
                while (true)
                {
                    SkipSpace();
                    if (Pos >= s.Length || s[Pos] != '"') throw Fail("expected a key string");
                    string key = ParseString();
                    SkipSpace();
                    if (Pos >= s.Length || s[Pos] != ':') throw Fail("expected ':'");
                    ++Pos;
                    result[key] = ParseValue(depth + 1);
                    SkipSpace();
                    if (Pos >= s.Length) throw Fail("unterminated object");
                    if (s[Pos] == ',') { ++Pos; continue; }
                    if (s[Pos] == '}') { ++Pos; return result; }
                    throw Fail("expected ',' or '}'");
                }
            }

            List<object> ParseArray(int depth)
            {
                var result = new List<object>();
                ++Pos;
                SkipSpace();
                if (Pos < s.Length && s[Pos] == ']') { ++Pos; return result; }
                while (true)
                {
                    result.Add(ParseValue(depth + 1));
                    SkipSpace();
                    if (Pos >= s.Length) throw Fail("unterminated array");
                    if (s[Pos] == ',') { ++Pos; continue; }
                    if (s[Pos] == ']') { ++Pos; return result; }
                    throw Fail("expected ',' or ']'");
                }
            }

            string ParseString()
            {
                ++Pos;
                var sb = new StringBuilder();
                while (true)
                {
                    if (Pos >= s.Length) throw Fail("unterminated string");
                    char c = s[Pos++];
                    if (c == '"') return sb.ToString();
                    if (c < 0x20) throw Fail("control character in string");
                    if (c != '\\') { sb.Append(c); continue; }
                    if (Pos >= s.Length) throw Fail("unterminated escape");
                    char e = s[Pos++];
                    switch (e)
                    {
                        case '"': sb.Append('"'); break;
                        case '\\': sb.Append('\\'); break;
                        case '/': sb.Append('/'); break;
                        case 'b': sb.Append('\b'); break;
                        case 'f': sb.Append('\f'); break;
                        case 'n': sb.Append('\n'); break;
                        case 'r': sb.Append('\r'); break;
                        case 't': sb.Append('\t'); break;
                        case 'u':
                            int code;
                            if (Pos + 4 > s.Length ||
                                !int.TryParse(s.Substring(Pos, 4), NumberStyles.AllowHexSpecifier,
                                              CultureInfo.InvariantCulture, out code))
                                throw Fail("bad \\u escape");
                            sb.Append((char)code);
                            Pos += 4;
                            break;
                        default: throw Fail("bad escape");
                    }
                }
            }

            double ParseNumber()
            {
                int start = Pos;
                while (Pos < s.Length && "+-0123456789.eE".IndexOf(s[Pos]) >= 0) ++Pos;
                double v;
                if (Pos == start ||
                    !double.TryParse(s.Substring(start, Pos - start), NumberStyles.Float,
                                     CultureInfo.InvariantCulture, out v))
                {
                    Pos = start;
                    throw Fail("expected a value");
                }
                return v;
            }
        }
    }
}
