package org.fclcert.eval;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.HashMap;
import java.util.Map;

/**
 * Just enough of the JVM class-file format (JVMS chapter 4) to define a final class with a no-argument
 * constructor that implements one interface with one method: loads, stores and arithmetic on doubles,
 * static calls, and the minimum and maximum of two locals as short forward branches. The class file is
 * version 49, checked by the type-inferring verifier, so no stack-map frames are needed. Used by
 * {@link MinMaxKernel} to turn a rule block into code the JIT compiles as one piece; nothing here knows
 * about fuzzy logic.
 */
final class ClassFile {
    // the opcodes the kernels use (JVMS 6.5)
    static final int DCONST_0 = 0x0e;
    static final int DCONST_1 = 0x0f;
    static final int DLOAD = 0x18;
    static final int ALOAD_1 = 0x2b;
    static final int DALOAD = 0x31;
    static final int DSTORE = 0x39;
    static final int DASTORE = 0x52;
    static final int DUP2 = 0x5c;
    static final int DADD = 0x63;
    static final int DSUB = 0x67;
    static final int DMUL = 0x6b;
    static final int DDIV = 0x6f;
    static final int RETURN = 0xb1;
    static final int ISTORE = 0x36;
    static final int ILOAD = 0x15;
    static final int IRETURN = 0xac;
    private static final int BIPUSH = 0x10;
    private static final int SIPUSH = 0x11;
    private static final int LDC_W = 0x13;
    private static final int LDC2_W = 0x14;
    private static final int INVOKESTATIC = 0xb8;
    private static final int INVOKESPECIAL = 0xb7;
    private static final int ALOAD_0 = 0x2a;
    private static final int WIDE = 0xc4;
    private static final int DCMPG = 0x98;
    private static final int IFGE = 0x9c;
    private static final int IFLE = 0x9e;
    private static final int GOTO = 0xa7;
    private static final int DCMPL = 0x97;
    private static final int IFLT = 0x9b;
    private static final int IFGT = 0x9d;
    private static final int IINC = 0x84;

    private final ByteArrayOutputStream pool = new ByteArrayOutputStream();
    private final DataOutputStream poolOut = new DataOutputStream(pool);
    private final Map<String, Integer> entries = new HashMap<>();
    private int count = 1;

    /** The bytes of one method body being written. */
    final Code code = new Code();

    /** Straight-line code: loads, stores, arithmetic and static calls; no branches. */
    final class Code {
        private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        private int maxLocals;
        /** Minimum and maximum as calls of Math.min/max (a third of the bytes), not as branches. */
        boolean compact;

        int size() {
            return bytes.size();
        }

        void op(int opcode) {
            bytes.write(opcode);
        }

        /** Pushes an int constant (array indices). */
        void intConst(int v) {
            if (v >= -128 && v <= 127) {
                op(BIPUSH);
                op(v);
            } else if (v >= -32768 && v <= 32767) {
                op(SIPUSH);
                u2(v);
            } else {
                op(LDC_W);
                u2(constant("I" + v, () -> {
                    poolOut.writeByte(3);
                    poolOut.writeInt(v);
                }));
            }
        }

        /** Pushes a double constant. */
        void doubleConst(double v) {
            if (Double.doubleToRawLongBits(v) == 0L) {
                op(DCONST_0);
            } else if (v == 1.0) {
                op(DCONST_1);
            } else {
                doubleConstWide(v);
            }
        }

        /** dload/dstore of a double local (two slots each). */
        void local(int opcode, int slot) {
            maxLocals = Math.max(maxLocals, slot + 2);
            if (slot <= 255) {
                op(opcode);
                op(slot);
            } else {
                op(WIDE);
                op(opcode);
                u2(slot);
            }
        }

        /**
         * Pushes a &lt; b ? a : b (least) or a &gt; b ? a : b (greatest) of two double locals: equal to
         * Math.min/max for numbers that are not NaN and not −0.0, and a branch the processor predicts is
         * cheaper than their branch-free sequence on the critical path; in {@link #compact} code, the call.
         */
        void pick(int a, int b, boolean least) {
            if (compact) {
                local(DLOAD, a);
                local(DLOAD, b);
                invokeStatic("java/lang/Math", least ? "min" : "max", "(DD)D");
                return;
            }
            local(DLOAD, a);
            local(DLOAD, b);
            op(DCMPG);
            op(least ? IFGE : IFLE);
            int loadSize = a <= 255 ? 2 : 4;
            u2(3 + loadSize + 3);               // past "load a; goto": to "load b"
            local(DLOAD, a);
            op(GOTO);
            u2(3 + (b <= 255 ? 2 : 4));         // past "load b"
            local(DLOAD, b);
        }

        /**
         * Pushes x &lt;= pivot ? (x − a) / rise : (d − x) / fall for the double local x (never NaN): the one
         * edge of a term with two that matters at x.
         */
        void edgeQuotient(int x, double pivot, double a, double rise, double d, double fall) {
            int load = x <= 255 ? 2 : 4;
            local(DLOAD, x);
            doubleConstWide(pivot);
            op(DCMPG);
            op(IFGT);
            u2(3 + load + 3 + 1 + 3 + 1 + 3);   // past the rising quotient and its goto
            local(DLOAD, x);
            doubleConstWide(a);
            op(DSUB);
            doubleConstWide(rise);
            op(DDIV);
            op(GOTO);
            u2(3 + 3 + load + 1 + 3 + 1);       // past the falling quotient
            doubleConstWide(d);
            local(DLOAD, x);
            op(DSUB);
            doubleConstWide(fall);
            op(DDIV);
        }

        /** Stores value into local acc when it is greater (acc = acc &lt; value ? value : acc). */
        void raise(int acc, int value) {
            if (compact) {
                local(DLOAD, acc);
                local(DLOAD, value);
                invokeStatic("java/lang/Math", "max", "(DD)D");
                local(DSTORE, acc);
                return;
            }
            local(DLOAD, acc);
            local(DLOAD, value);
            op(DCMPG);
            op(IFGE);
            u2(3 + (value <= 255 ? 2 : 4) + (acc <= 255 ? 2 : 4));
            local(DLOAD, value);
            local(DSTORE, acc);
        }

        /**
         * values[slot] = local q when min &lt;= q &lt;= max (NaN is not), else increments the int local flag
         * (index at most 255). The array is in local 1.
         */
        void storeWithin(int q, double min, double max, int slot, int flag) {
            int load = q <= 255 ? 2 : 4;
            int constSize = 3;                   // ldc2_w
            int store = 1 + intConstSize(slot) + load + 1 + 3;   // aload_1, index, dload q, dastore, goto
            local(DLOAD, q);
            doubleConstWide(min);
            op(DCMPL);                           // NaN: -1, fails
            op(IFLT);
            u2(3 + load + constSize + 1 + 3 + store);
            local(DLOAD, q);
            doubleConstWide(max);
            op(DCMPG);                           // NaN: 1, fails
            op(IFGT);
            u2(3 + store);
            op(ALOAD_1);                         // values
            intConst(slot);
            local(DLOAD, q);
            op(DASTORE);
            op(GOTO);
            u2(3 + 3);                           // past the iinc
            op(IINC);
            op(flag);
            op(1);
        }

        private int intConstSize(int v) {
            return v >= -128 && v <= 127 ? 2 : v >= -32768 && v <= 32767 ? 3 : 3;
        }

        /** A double constant always as ldc2_w (three bytes), so that branch offsets around it are fixed. */
        private void doubleConstWide(double v) {
            op(LDC2_W);
            long bits = Double.doubleToRawLongBits(v);
            u2(constant("D" + bits, () -> {
                poolOut.writeByte(6);
                poolOut.writeLong(bits);
            }, 2));
        }

        void invokeStatic(String owner, String name, String descriptor) {
            op(INVOKESTATIC);
            u2(methodRef(owner, name, descriptor));
        }

        private void u2(int v) {
            bytes.write(v >>> 8);
            bytes.write(v);
        }
    }

    private interface Writer {
        void write() throws IOException;
    }

    private int constant(String key, Writer writer) {
        return constant(key, writer, 1);
    }

    private int constant(String key, Writer writer, int slots) {
        Integer at = entries.get(key);
        if (at != null) {
            return at;
        }
        try {
            writer.write();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        int index = count;
        count += slots;
        entries.put(key, index);
        return index;
    }

    private int utf8(String s) {
        return constant("U" + s, () -> {
            poolOut.writeByte(1);
            poolOut.writeUTF(s);
        });
    }

    private int classRef(String internalName) {
        int name = utf8(internalName);
        return constant("C" + internalName, () -> {
            poolOut.writeByte(7);
            poolOut.writeShort(name);
        });
    }

    private int methodRef(String owner, String name, String descriptor) {
        int c = classRef(owner);
        int n = utf8(name);
        int d = utf8(descriptor);
        int nat = constant("N" + name + descriptor, () -> {
            poolOut.writeByte(12);
            poolOut.writeShort(n);
            poolOut.writeShort(d);
        });
        return constant("M" + owner + "." + name + descriptor, () -> {
            poolOut.writeByte(10);
            poolOut.writeShort(c);
            poolOut.writeShort(nat);
        });
    }

    /**
     * The class file of {@code thisClass} (internal name) implementing {@code iface} with {@link #code} as
     * the body of {@code method}; {@code argSlots} are the local slots its arguments take (this included).
     */
    byte[] toBytes(String thisClass, String iface, String method, String descriptor, int argSlots) {
        int self = classRef(thisClass);
        int object = classRef("java/lang/Object");
        int itf = classRef(iface);
        int init = utf8("<init>");
        int voidDesc = utf8("()V");
        int objectInit = methodRef("java/lang/Object", "<init>", "()V");
        int codeAttr = utf8("Code");
        int name = utf8(method);
        int desc = utf8(descriptor);
        try {
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            DataOutputStream o = new DataOutputStream(out);
            o.writeInt(0xCAFEBABE);
            o.writeShort(0);
            o.writeShort(49);                    // Java 5: verified by type inference, no stack-map frames
            o.writeShort(count);
            poolOut.flush();
            pool.writeTo(out);
            o.writeShort(0x0001 | 0x0010 | 0x0020);   // public final super
            o.writeShort(self);
            o.writeShort(object);
            o.writeShort(1);
            o.writeShort(itf);
            o.writeShort(0);                     // fields
            o.writeShort(2);                     // methods
            // public <init>() { super(); }
            o.writeShort(0x0001);
            o.writeShort(init);
            o.writeShort(voidDesc);
            o.writeShort(1);
            o.writeShort(codeAttr);
            byte[] initCode = {(byte) ALOAD_0, (byte) INVOKESPECIAL, (byte) (objectInit >>> 8), (byte) objectInit,
                (byte) RETURN};
            o.writeInt(12 + initCode.length);
            o.writeShort(1);
            o.writeShort(1);
            o.writeInt(initCode.length);
            o.write(initCode);
            o.writeShort(0);
            o.writeShort(0);
            // public final <method>
            byte[] body = code.bytes.toByteArray();
            o.writeShort(0x0001 | 0x0010);
            o.writeShort(name);
            o.writeShort(desc);
            o.writeShort(1);
            o.writeShort(codeAttr);
            o.writeInt(12 + body.length);
            o.writeShort(16);                    // max stack: the deepest expression pushes a handful of doubles
            o.writeShort(Math.max(argSlots, code.maxLocals));
            o.writeInt(body.length);
            o.write(body);
            o.writeShort(0);
            o.writeShort(0);
            o.writeShort(0);                     // class attributes
            o.flush();
            return out.toByteArray();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
