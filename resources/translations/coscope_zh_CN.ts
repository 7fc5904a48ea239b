<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>AboutBox</name>
    <message>
        <source>CANopen bus analyzer and servo-drive commissioning tool.</source>
        <translation>CANopen 总线分析与伺服驱动器调试工具。</translation>
    </message>
    <message>
        <source>Version %1, source revision %2, built with Qt %3 (running on Qt %4).</source>
        <translation>版本 %1，源代码修订 %2，使用 Qt %3 构建（运行于 Qt %4）。</translation>
    </message>
    <message>
        <source>CoScope is free software under the GNU General Public License, version 3 or later (GPL-3.0-or-later), and comes with no warranty.</source>
        <translation>CoScope 是按 GNU 通用公共许可证第 3 版或更高版本（GPL-3.0-or-later）发布的自由软件，不提供任何担保。</translation>
    </message>
    <message>
        <source>It is built on:</source>
        <translation>它基于以下软件构建：</translation>
    </message>
    <message>
        <source>Qt, under the GNU Lesser General Public License version 3 (LGPLv3)</source>
        <translation>Qt，按 GNU 宽通用公共许可证第 3 版（LGPLv3）</translation>
    </message>
    <message>
        <source>QCustomPlot, under the GNU General Public License version 3 (GPLv3)</source>
        <translation>QCustomPlot，按 GNU 通用公共许可证第 3 版（GPLv3）</translation>
    </message>
    <message>
        <source>spdlog and fmt, under the MIT license</source>
        <translation>spdlog 与 fmt，按 MIT 许可证</translation>
    </message>
    <message>
        <source>About CoScope</source>
        <translation>关于 CoScope</translation>
    </message>
</context>
<context>
    <name>ApplyText</name>
    <message>
        <source>Node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>Node %1 (%2)</source>
        <translation>节点 %1（%2）</translation>
    </message>
    <message>
        <source>the node does not answer</source>
        <translation>节点没有响应</translation>
    </message>
    <message>
        <source>another device answers at this node-ID</source>
        <translation>此节点 ID 由其他设备响应</translation>
    </message>
    <message>
        <source>not in the project</source>
        <translation>不在项目中</translation>
    </message>
    <message>
        <source>no dictionary for the node (%1)</source>
        <translation>此节点没有字典（%1）</translation>
    </message>
    <message>
        <source>written</source>
        <translation>已写入</translation>
    </message>
    <message>
        <source>nothing to write, already as in the project</source>
        <translation>无需写入，已与项目相同</translation>
    </message>
    <message>
        <source>refused, old values put back</source>
        <translation>被拒绝，已写回旧值</translation>
    </message>
    <message>
        <source>refused, old values NOT all put back</source>
        <translation>被拒绝，旧值“未”全部写回</translation>
    </message>
    <message>
        <source>not written: a node before refused</source>
        <translation>未写入：之前的节点拒绝了写入</translation>
    </message>
    <message>
        <source>skipped</source>
        <translation>已跳过</translation>
    </message>
    <message>
        <source>%1: not written: %2</source>
        <translation>%1：未写入：%2</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n SDO write(s)</source>
        <translation>
            <numerusform>%1：%n 次 SDO 写入</numerusform>
        </translation>
    </message>
    <message>
        <source>write %1 %2 = %3</source>
        <translation>写入 %1 %2 = %3</translation>
    </message>
    <message>
        <source>%1  (now %2)</source>
        <translation>%1  （当前 %2）</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message numerus="yes">
        <source> - %n object(s) written</source>
        <translation>
            <numerusform> - 已写入 %n 个对象</numerusform>
        </translation>
    </message>
    <message>
        <source>written: %1</source>
        <translation>已写入：%1</translation>
    </message>
    <message>
        <source>REFUSED: %1: %2</source>
        <translation>被拒绝：%1：%2</translation>
    </message>
    <message>
        <source>put back: %1</source>
        <translation>已写回：%1</translation>
    </message>
    <message>
        <source>NOT put back: %1: %2</source>
        <translation>未写回：%1：%2</translation>
    </message>
</context>
<context>
    <name>CoreText</name>
    <message>
        <source>Not ready to switch on</source>
        <translation>正在初始化</translation>
    </message>
    <message>
        <source>Switch on disabled</source>
        <translation>伺服无故障</translation>
    </message>
    <message>
        <source>Ready to switch on</source>
        <translation>伺服准备好</translation>
    </message>
    <message>
        <source>Switched on</source>
        <translation>等待打开使能</translation>
    </message>
    <message>
        <source>Operation enabled</source>
        <translation>伺服已使能</translation>
    </message>
    <message>
        <source>Quick stop active</source>
        <translation>快速停机中</translation>
    </message>
    <message>
        <source>Fault reaction active</source>
        <translation>正在故障停机</translation>
    </message>
    <message>
        <source>Fault</source>
        <translation>故障</translation>
    </message>
    <message>
        <source>Unknown state</source>
        <translation>未知状态</translation>
    </message>
    <message>
        <source>ready to switch on</source>
        <translation>伺服准备好</translation>
    </message>
    <message>
        <source>switched on</source>
        <translation>等待打开使能</translation>
    </message>
    <message>
        <source>operation enabled</source>
        <translation>伺服已使能</translation>
    </message>
    <message>
        <source>fault</source>
        <translation>故障</translation>
    </message>
    <message>
        <source>voltage enabled</source>
        <translation>电压已启用</translation>
    </message>
    <message>
        <source>quick stop</source>
        <translation>快速停止</translation>
    </message>
    <message>
        <source>switch on disabled</source>
        <translation>伺服无故障</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>manufacturer specific (bit 8)</source>
        <translation>制造商定义（位 8）</translation>
    </message>
    <message>
        <source>remote</source>
        <translation>远程</translation>
    </message>
    <message>
        <source>target reached</source>
        <translation>已到达目标</translation>
    </message>
    <message>
        <source>internal limit active</source>
        <translation>内部限制作用中</translation>
    </message>
    <message>
        <source>operation mode specific (bit 12)</source>
        <translation>按运行模式而定（位 12）</translation>
    </message>
    <message>
        <source>operation mode specific (bit 13)</source>
        <translation>按运行模式而定（位 13）</translation>
    </message>
    <message>
        <source>manufacturer specific (bit 14)</source>
        <translation>制造商定义（位 14）</translation>
    </message>
    <message>
        <source>manufacturer specific (bit 15)</source>
        <translation>制造商定义（位 15）</translation>
    </message>
    <message>
        <source>Shutdown</source>
        <translation>关闭（Shutdown）</translation>
    </message>
    <message>
        <source>Switch on</source>
        <translation>接通主回路（Switch on）</translation>
    </message>
    <message>
        <source>Switch on + enable operation</source>
        <translation>接通主回路＋使能运行</translation>
    </message>
    <message>
        <source>Disable voltage</source>
        <translation>断开电压（Disable voltage）</translation>
    </message>
    <message>
        <source>Quick stop</source>
        <translation>快速停止</translation>
    </message>
    <message>
        <source>Disable operation</source>
        <translation>禁止运行（Disable operation）</translation>
    </message>
    <message>
        <source>Enable operation</source>
        <translation>运行使能</translation>
    </message>
    <message>
        <source>Fault reset</source>
        <translation>故障复位</translation>
    </message>
    <message>
        <source>Switch on / disable operation</source>
        <translation>接通主回路／禁止运行</translation>
    </message>
    <message>
        <source>No command</source>
        <translation>无命令</translation>
    </message>
    <message>
        <source>No mode</source>
        <translation>无模式</translation>
    </message>
    <message>
        <source>Profile position (PP)</source>
        <translation>轮廓位置（PP）</translation>
    </message>
    <message>
        <source>Velocity (VL)</source>
        <translation>速度（VL）</translation>
    </message>
    <message>
        <source>Profile velocity (PV)</source>
        <translation>轮廓速度（PV）</translation>
    </message>
    <message>
        <source>Profile torque (PT)</source>
        <translation>轮廓转矩（PT）</translation>
    </message>
    <message>
        <source>Homing (HM)</source>
        <translation>原点回零（HM）</translation>
    </message>
    <message>
        <source>Interpolated position (IP)</source>
        <translation>插补位置（IP）</translation>
    </message>
    <message>
        <source>Cyclic synchronous position (CSP)</source>
        <translation>同步位置（CSP）</translation>
    </message>
    <message>
        <source>Cyclic synchronous velocity (CSV)</source>
        <translation>同步速度（CSV）</translation>
    </message>
    <message>
        <source>Cyclic synchronous torque (CST)</source>
        <translation>同步转矩（CST）</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>启动</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Enter pre-operational</source>
        <translation>进入预操作状态</translation>
    </message>
    <message>
        <source>Reset node</source>
        <translation>复位节点</translation>
    </message>
    <message>
        <source>Reset communication</source>
        <translation>复位通信</translation>
    </message>
    <message>
        <source>Boot-up</source>
        <translation>启动（Boot-up）</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Operational</source>
        <translation>操作状态</translation>
    </message>
    <message>
        <source>Pre-operational</source>
        <translation>预操作状态</translation>
    </message>
    <message>
        <source>Toggle bit not alternated</source>
        <translation>翻转位未交替</translation>
    </message>
    <message>
        <source>SDO protocol timed out</source>
        <translation>SDO 协议超时</translation>
    </message>
    <message>
        <source>Client/server command specifier not valid or unknown</source>
        <translation>客户端／服务器命令标识符无效或未知</translation>
    </message>
    <message>
        <source>Invalid block size (block mode only)</source>
        <translation>块大小无效（仅限块模式）</translation>
    </message>
    <message>
        <source>Invalid sequence number (block mode only)</source>
        <translation>序列号无效（仅限块模式）</translation>
    </message>
    <message>
        <source>CRC error (block mode only)</source>
        <translation>CRC 错误（仅限块模式）</translation>
    </message>
    <message>
        <source>Out of memory</source>
        <translation>内存不足</translation>
    </message>
    <message>
        <source>Unsupported access to an object</source>
        <translation>不支持的对象访问方式</translation>
    </message>
    <message>
        <source>Attempt to read a write-only object</source>
        <translation>尝试读取只写对象</translation>
    </message>
    <message>
        <source>Attempt to write a read-only object</source>
        <translation>尝试写入只读对象</translation>
    </message>
    <message>
        <source>Object does not exist in the object dictionary</source>
        <translation>对象字典中没有此对象</translation>
    </message>
    <message>
        <source>Object cannot be mapped to the PDO</source>
        <translation>对象无法映射到 PDO</translation>
    </message>
    <message>
        <source>The number and length of the objects to be mapped would exceed the PDO length</source>
        <translation>要映射的对象数量与长度会超过 PDO 长度</translation>
    </message>
    <message>
        <source>General parameter incompatibility reason</source>
        <translation>一般性参数不兼容</translation>
    </message>
    <message>
        <source>General internal incompatibility in the device</source>
        <translation>设备内部一般性不兼容</translation>
    </message>
    <message>
        <source>Access failed due to a hardware error</source>
        <translation>硬件错误导致访问失败</translation>
    </message>
    <message>
        <source>Data type does not match, length of service parameter does not match</source>
        <translation>数据类型不符，服务参数长度不符</translation>
    </message>
    <message>
        <source>Data type does not match, length of service parameter too high</source>
        <translation>数据类型不符，服务参数长度过长</translation>
    </message>
    <message>
        <source>Data type does not match, length of service parameter too low</source>
        <translation>数据类型不符，服务参数长度过短</translation>
    </message>
    <message>
        <source>Sub-index does not exist</source>
        <translation>子索引不存在</translation>
    </message>
    <message>
        <source>Invalid value for parameter (download only)</source>
        <translation>参数值无效（仅限下载）</translation>
    </message>
    <message>
        <source>Value of parameter written too high (download only)</source>
        <translation>写入的参数值过高（仅限下载）</translation>
    </message>
    <message>
        <source>Value of parameter written too low (download only)</source>
        <translation>写入的参数值过低（仅限下载）</translation>
    </message>
    <message>
        <source>Maximum value is less than minimum value</source>
        <translation>最大值小于最小值</translation>
    </message>
    <message>
        <source>Resource not available: SDO connection</source>
        <translation>资源不可用：SDO 连接</translation>
    </message>
    <message>
        <source>General error</source>
        <translation>一般错误</translation>
    </message>
    <message>
        <source>Data cannot be transferred or stored to the application</source>
        <translation>数据无法发送或保存到应用程序</translation>
    </message>
    <message>
        <source>Data cannot be transferred or stored to the application because of local control</source>
        <translation>因本地控制，数据无法发送或保存到应用程序</translation>
    </message>
    <message>
        <source>Data cannot be transferred or stored to the application because of the present device state</source>
        <translation>因设备当前的状态，数据无法发送或保存到应用程序</translation>
    </message>
    <message>
        <source>Object dictionary dynamic generation fails or no object dictionary is present</source>
        <translation>对象字典动态产生失败，或没有对象字典</translation>
    </message>
    <message>
        <source>No data available</source>
        <translation>没有可用的数据</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>已关闭</translation>
    </message>
    <message>
        <source>opening</source>
        <translation>打开中</translation>
    </message>
    <message>
        <source>open</source>
        <translation>已打开</translation>
    </message>
    <message>
        <source>error</source>
        <translation>错误</translation>
    </message>
    <message>
        <source>NMT %1, node %2</source>
        <translation>NMT %1，节点 %2</translation>
    </message>
    <message>
        <source>NMT %1, all nodes</source>
        <translation>NMT %1，所有节点</translation>
    </message>
    <message>
        <source>NMT (malformed)</source>
        <translation>NMT（格式错误）</translation>
    </message>
    <message>
        <source>NMT command with %1 bytes; CiA 301 requires 2</source>
        <translation>NMT 命令有 %1 字节；CiA 301 规定为 2</translation>
    </message>
    <message>
        <source>unknown NMT command specifier 0x%1</source>
        <translation>未知的 NMT 命令码 0x%1</translation>
    </message>
    <message>
        <source>NMT target node-ID %1 is outside 0..127</source>
        <translation>NMT 目标节点 ID %1 不在 0..127 之间</translation>
    </message>
    <message>
        <source>Node guarding request, node %1</source>
        <translation>节点保护请求，节点 %1</translation>
    </message>
    <message>
        <source>error control frame with %1 bytes; CiA 301 requires 1</source>
        <translation>错误控制帧有 %1 字节；CiA 301 规定为 1</translation>
    </message>
    <message>
        <source>Error control (malformed), node %1</source>
        <translation>错误控制（格式错误），节点 %1</translation>
    </message>
    <message>
        <source>unknown NMT state 0x%1</source>
        <translation>未知的 NMT 状态 0x%1</translation>
    </message>
    <message>
        <source>node guarding toggle bit did not alternate (still %1)</source>
        <translation>节点保护的切换位没有交替（仍为 %1）</translation>
    </message>
    <message>
        <source>Boot-up, node %1</source>
        <translation>启动报文，节点 %1</translation>
    </message>
    <message>
        <source>Node guarding, node %1: %2, toggle %3</source>
        <translation>节点保护，节点 %1：%2，切换位 %3</translation>
    </message>
    <message>
        <source>Heartbeat, node %1: %2</source>
        <translation>心跳，节点 %1：%2</translation>
    </message>
    <message>
        <source>SYNC counter %1</source>
        <translation>SYNC 计数 %1</translation>
    </message>
    <message>
        <source>SYNC with %1 bytes; CiA 301 allows 0 or 1</source>
        <translation>SYNC 有 %1 字节；CiA 301 只允许 0 或 1</translation>
    </message>
    <message>
        <source>SYNC counter %1 is outside 1..240</source>
        <translation>SYNC 计数 %1 不在 1..240 之间</translation>
    </message>
    <message>
        <source>EMCY node %1: %2 %3, register 0x%4</source>
        <translation>EMCY 节点 %1：%2 %3，错误寄存器 0x%4</translation>
    </message>
    <message>
        <source>EMCY (malformed), node %1</source>
        <translation>EMCY（格式错误），节点 %1</translation>
    </message>
    <message>
        <source>EMCY with %1 bytes; CiA 301 requires 8</source>
        <translation>EMCY 有 %1 字节；CiA 301 规定为 8</translation>
    </message>
    <message>
        <source>M%1 alarm %2</source>
        <translation>M%1 报警 %2</translation>
    </message>
    <message>
        <source>%1 0x%2 (not in the table)</source>
        <translation>%1 0x%2（不在报警表中）</translation>
    </message>
    <message>
        <source>SDO write node %1 %2 = %3</source>
        <translation>SDO 写入 节点 %1 %2 = %3</translation>
    </message>
    <message>
        <source>SDO write node %1 %2, %3 bytes (segmented)</source>
        <translation>SDO 写入 节点 %1 %2，%3 字节（分段）</translation>
    </message>
    <message>
        <source>SDO write node %1 %2 (segmented)</source>
        <translation>SDO 写入 节点 %1 %2（分段）</translation>
    </message>
    <message>
        <source>SDO write ok node %1 %2</source>
        <translation>SDO 写入成功 节点 %1 %2</translation>
    </message>
    <message>
        <source>SDO read node %1 %2 = %3</source>
        <translation>SDO 读取 节点 %1 %2 = %3</translation>
    </message>
    <message>
        <source>SDO read node %1 %2, %3 bytes (segmented)</source>
        <translation>SDO 读取 节点 %1 %2，%3 字节（分段）</translation>
    </message>
    <message>
        <source>SDO read node %1 %2 (segmented)</source>
        <translation>SDO 读取 节点 %1 %2（分段）</translation>
    </message>
    <message>
        <source>SDO read node %1 %2</source>
        <translation>SDO 读取 节点 %1 %2</translation>
    </message>
    <message>
        <source>SDO abort node %1 %2: %3 %4</source>
        <translation>SDO 中止 节点 %1 %2：%3 %4</translation>
    </message>
    <message>
        <source>SDO %1 node %2, toggle %3, %4 bytes, last</source>
        <translation>SDO %1 节点 %2，切换位 %3，%4 字节，最后一段</translation>
    </message>
    <message>
        <source>SDO %1 node %2, toggle %3, %4 bytes</source>
        <translation>SDO %1 节点 %2，切换位 %3，%4 字节</translation>
    </message>
    <message>
        <source>SDO block segment %1 node %2, %3 bytes, last</source>
        <translation>SDO 块分段 %1 节点 %2，%3 字节，最后一段</translation>
    </message>
    <message>
        <source>SDO block segment %1 node %2, %3 bytes</source>
        <translation>SDO 块分段 %1 节点 %2，%3 字节</translation>
    </message>
    <message>
        <source>SDO %1 node %2, ackseq %3, block size %4</source>
        <translation>SDO %1 节点 %2，确认序列号 %3，块大小 %4</translation>
    </message>
    <message>
        <source>SDO %1 node %2, %3 unused bytes, CRC 0x%4</source>
        <translation>SDO %1 节点 %2，%3 个未使用字节，CRC 0x%4</translation>
    </message>
    <message>
        <source>SDO node %1 (invalid)</source>
        <translation>SDO 节点 %1（无效）</translation>
    </message>
    <message>
        <source>SDO remote frame, node %1</source>
        <translation>SDO 远程帧，节点 %1</translation>
    </message>
    <message>
        <source>remote frame on an SDO COB-ID</source>
        <translation>SDO COB-ID 上出现远程帧</translation>
    </message>
    <message>
        <source>unknown abort code</source>
        <translation>未知的中止码</translation>
    </message>
    <message>
        <source>initiate download request</source>
        <translation>起始下载请求</translation>
    </message>
    <message>
        <source>download segment request</source>
        <translation>下载分段请求</translation>
    </message>
    <message>
        <source>initiate upload request</source>
        <translation>起始上传请求</translation>
    </message>
    <message>
        <source>upload segment request</source>
        <translation>上传分段请求</translation>
    </message>
    <message>
        <source>initiate download response</source>
        <translation>起始下载响应</translation>
    </message>
    <message>
        <source>download segment response</source>
        <translation>下载分段响应</translation>
    </message>
    <message>
        <source>initiate upload response</source>
        <translation>起始上传响应</translation>
    </message>
    <message>
        <source>upload segment response</source>
        <translation>上传分段响应</translation>
    </message>
    <message>
        <source>block upload initiate</source>
        <translation>块上传起始</translation>
    </message>
    <message>
        <source>block upload start</source>
        <translation>块上传开始</translation>
    </message>
    <message>
        <source>block upload ack</source>
        <translation>块上传确认</translation>
    </message>
    <message>
        <source>block upload end</source>
        <translation>块上传结束</translation>
    </message>
    <message>
        <source>block upload end response</source>
        <translation>块上传结束响应</translation>
    </message>
    <message>
        <source>block upload initiate response</source>
        <translation>块上传起始响应</translation>
    </message>
    <message>
        <source>block download initiate</source>
        <translation>块下载起始</translation>
    </message>
    <message>
        <source>block download initiate response</source>
        <translation>块下载起始响应</translation>
    </message>
    <message>
        <source>block download ack</source>
        <translation>块下载确认</translation>
    </message>
    <message>
        <source>block download end</source>
        <translation>块下载结束</translation>
    </message>
    <message>
        <source>block download end response</source>
        <translation>块下载结束响应</translation>
    </message>
    <message>
        <source>%1 node %2: remote request</source>
        <translation>%1 节点 %2：远程请求</translation>
    </message>
    <message>
        <source>%1 of node %2 is not valid (COB-ID 0x%3) but was seen on the bus</source>
        <translation>节点 %2 的 %1 无效（COB-ID 0x%3），却出现在总线上</translation>
    </message>
    <message>
        <source>%1 has %2 bytes but its mapping needs %3</source>
        <translation>%1 有 %2 字节，但它的映射需要 %3</translation>
    </message>
    <message>
        <source>not CANopen (29-bit identifier)</source>
        <translation>不是 CANopen（29 位标识符）</translation>
    </message>
    <message>
        <source>unknown COB-ID</source>
        <translation>未知的 COB-ID</translation>
    </message>
    <message>
        <source>new SDO request for %1 while the transfer of %2 was unfinished (abandoned)</source>
        <translation>%2 的传输尚未完成时又出现 %1 的 SDO 请求（已放弃前者）</translation>
    </message>
    <message>
        <source>response for %1 but the request was for %2</source>
        <translation>响应的是 %1，但请求的是 %2</translation>
    </message>
    <message>
        <source>SDO transfer of %1 carried %2 bytes but announced %3</source>
        <translation>%1 的 SDO 传输带了 %2 字节，但声明为 %3</translation>
    </message>
    <message>
        <source>block ack acknowledges %1 segments, %2 were sent</source>
        <translation>块确认了 %1 个分段，实际发送 %2 个</translation>
    </message>
    <message>
        <source>SDO block CRC 0x%1 does not match the data (0x%2)</source>
        <translation>SDO 块 CRC 0x%1 与数据不符（0x%2）</translation>
    </message>
    <message>
        <source>unexpected SDO %1 (%2)</source>
        <translation>非预期的 SDO %1（%2）</translation>
    </message>
    <message>
        <source>no transfer in progress</source>
        <translation>没有进行中的传输</translation>
    </message>
    <message>
        <source>transfer of %1 in progress</source>
        <translation>%1 的传输进行中</translation>
    </message>
    <message>
        <source>SDO toggle bit %1, expected %2</source>
        <translation>SDO 切换位为 %1，预期为 %2</translation>
    </message>
    <message>
        <source>abort names %1 but the transfer in progress is %2</source>
        <translation>中止指的是 %1，但进行中的传输是 %2</translation>
    </message>
    <message>
        <source>block segment %1, expected %2</source>
        <translation>块分段 %1，预期为 %2</translation>
    </message>
    <message>
        <source>block segment %1 beyond the block size %2</source>
        <translation>块分段 %1 超出块大小 %2</translation>
    </message>
    <message>
        <source>generic error</source>
        <translation>一般错误</translation>
    </message>
    <message>
        <source>current</source>
        <translation>电流</translation>
    </message>
    <message>
        <source>voltage</source>
        <translation>电压</translation>
    </message>
    <message>
        <source>temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <source>communication error</source>
        <translation>通信错误</translation>
    </message>
    <message>
        <source>device profile specific</source>
        <translation>设备规范定义</translation>
    </message>
    <message>
        <source>reserved</source>
        <translation>保留</translation>
    </message>
    <message>
        <source>manufacturer specific</source>
        <translation>制造商自定义</translation>
    </message>
    <message>
        <source>once</source>
        <translation>1 次</translation>
    </message>
    <message>
        <source>%1 times</source>
        <translation>%1 次</translation>
    </message>
    <message>
        <source>node %1 (bus %2)</source>
        <translation>节点 %1（总线 %2）</translation>
    </message>
    <message>
        <source>node %1 rebooted %2 (boot-up without an NMT reset)</source>
        <translation>节点 %1 重新启动了 %2（没有 NMT 重置却发送启动报文）</translation>
    </message>
    <message>
        <source>node %1 heartbeat stopped: nothing for %2 (period %3)</source>
        <translation>节点 %1 心跳停止：%2 没有任何消息（周期 %3）</translation>
    </message>
    <message>
        <source>node %1 heartbeat stopped: nothing for %2 (period %3), 1017h was set to 0</source>
        <translation>节点 %1 心跳停止：%2 没有任何消息（周期 %3），1017h 已被设为 0</translation>
    </message>
    <message>
        <source>node %1 guarding stopped: nothing for %2 (period %3)</source>
        <translation>节点 %1 节点保护停止：%2 没有任何消息（周期 %3）</translation>
    </message>
    <message>
        <source>node %1 heartbeat lost %2 (longest gap %3, period %4)</source>
        <translation>节点 %1 心跳丢失 %2（最长间隔 %3，周期 %4）</translation>
    </message>
    <message>
        <source>node %1 guarding lost %2 (longest gap %3, period %4)</source>
        <translation>节点 %1 节点保护丢失 %2（最长间隔 %3，周期 %4）</translation>
    </message>
    <message>
        <source>%1 more EMCY from node %2</source>
        <translation>节点 %2 还有 %1 条 EMCY</translation>
    </message>
    <message>
        <source>EMCY %1 %2 from node %3 at %4</source>
        <translation>EMCY %1 %2，来自节点 %3，时间 %4</translation>
    </message>
    <message>
        <source>node %1 left %2 SDO request unanswered</source>
        <translation>节点 %1 有 %2 个 SDO 请求没有响应</translation>
    </message>
    <message>
        <source>node %1 left %2 SDO requests unanswered</source>
        <translation>节点 %1 有 %2 个 SDO 请求没有响应</translation>
    </message>
    <message>
        <source>node %1 aborted SDO %2 with %3 %4</source>
        <translation>节点 %1 以 %3 %4 中止 SDO %2</translation>
    </message>
    <message>
        <source>node %1 answered SDO in %2 p99 (max %3)</source>
        <translation>节点 %1 的 SDO 响应时间 p99 为 %2（最大 %3）</translation>
    </message>
    <message>
        <source>node %1 heartbeat late %2 (over 1.5x the %3 period)</source>
        <translation>节点 %1 心跳延迟 %2（超过周期 %3 的 1.5 倍）</translation>
    </message>
    <message>
        <source>node %1 guarding late %2 (over 1.5x the %3 period)</source>
        <translation>节点 %1 节点保护延迟 %2（超过周期 %3 的 1.5 倍）</translation>
    </message>
    <message>
        <source>%1 CAN error frame</source>
        <translation>%1 个 CAN 错误帧</translation>
    </message>
    <message>
        <source>%1 CAN error frames</source>
        <translation>%1 个 CAN 错误帧</translation>
    </message>
    <message>
        <source>%1 SYNC cycle missing (period %2)</source>
        <translation>缺少 %1 个 SYNC 周期（周期 %2）</translation>
    </message>
    <message>
        <source>%1 SYNC cycles missing (period %2)</source>
        <translation>缺少 %1 个 SYNC 周期（周期 %2）</translation>
    </message>
    <message>
        <source>bus load peaks at %1 % (average %2 %) at %3 bit/s</source>
        <translation>总线负载峰值 %1 %（平均 %2 %），波特率 %3 bit/s</translation>
    </message>
    <message>
        <source>RPDO (%1) sent to node %2, which never answers</source>
        <translation>RPDO（%1）送往节点 %2，但它从未响应</translation>
    </message>
    <message>
        <source>TPDO (%1) sent to node %2, which never answers</source>
        <translation>TPDO（%1）送往节点 %2，但它从未响应</translation>
    </message>
    <message>
        <source>%1 of node %2 (%3) every %4 jitters by %5</source>
        <translation>节点 %2 的 %1（%3）每 %4 一次，抖动 %5</translation>
    </message>
    <message>
        <source>RPDO%1 of node %2 (%3) is valid but nobody sends it</source>
        <translation>节点 %2 的 RPDO%1（%3）有效，但没有人发送它</translation>
    </message>
    <message>
        <source>%1 node-ID (%2..%3) got an SDO request and never answered: a network scan, or devices missing</source>
        <translation>%1 个节点 ID（%2..%3）收到 SDO 请求却从未响应：可能是网络扫描，或设备不在</translation>
    </message>
    <message>
        <source>%1 node-IDs (%2..%3) got an SDO request and never answered: a network scan, or devices missing</source>
        <translation>%1 个节点 ID（%2..%3）收到 SDO 请求却从未响应：可能是网络扫描，或设备不在</translation>
    </message>
    <message>
        <source>%1 frame is not CANopen</source>
        <translation>%1 帧不是 CANopen</translation>
    </message>
    <message>
        <source>%1 frames are not CANopen</source>
        <translation>%1 帧不是 CANopen</translation>
    </message>
    <message>
        <source>Write %1 = %2 on node %3</source>
        <translation>在节点 %3 写入 %1 = %2</translation>
    </message>
    <message>
        <source>Read %1 from node %2</source>
        <translation>从节点 %2 读取 %1</translation>
    </message>
    <message>
        <source>Check %1 = %2 on node %3</source>
        <translation>确认节点 %3 的 %1 = %2</translation>
    </message>
    <message>
        <source>Check %1 = %2 (mask %3) on node %4</source>
        <translation>确认节点 %4 的 %1 = %2（掩码 %3）</translation>
    </message>
    <message>
        <source>NMT %1 to all nodes</source>
        <translation>对所有节点发送 NMT %1</translation>
    </message>
    <message>
        <source>NMT %1 to node %2</source>
        <translation>对节点 %2 发送 NMT %1</translation>
    </message>
    <message>
        <source>LSS: every device to configuration state</source>
        <translation>LSS：所有设备进入设置状态</translation>
    </message>
    <message>
        <source>LSS: every device back to waiting state</source>
        <translation>LSS：所有设备回到等待状态</translation>
    </message>
    <message>
        <source>LSS: select the device with vendor %1h, product %2h, revision %3h, serial %4h</source>
        <translation>LSS：选中厂商 %1h、产品 %2h、版本 %3h、序列号 %4h 的设备</translation>
    </message>
    <message>
        <source>LSS: set node-ID to unconfigured (FFh)</source>
        <translation>LSS：将节点 ID 设为未设置（FFh）</translation>
    </message>
    <message>
        <source>LSS: set node-ID %1</source>
        <translation>LSS：设置节点 ID 为 %1</translation>
    </message>
    <message>
        <source>LSS: set bit rate %1</source>
        <translation>LSS：设置波特率为 %1</translation>
    </message>
    <message>
        <source>LSS: store configuration</source>
        <translation>LSS：保存设置</translation>
    </message>
    <message>
        <source>LSS: switch to the new bit rate (switch delay %1 ms)</source>
        <translation>LSS：切换到新波特率（切换延迟 %1 ms）</translation>
    </message>
    <message>
        <source>Wait %1 ms</source>
        <translation>等待 %1 ms</translation>
    </message>
    <message>
        <source>Wait up to %1 ms for node %2 (boot-up or heartbeat)</source>
        <translation>最多等待 %1 ms，直到节点 %2 报告（启动报文或心跳）</translation>
    </message>
    <message>
        <source>Reconnect the adapter at %1</source>
        <translation>以 %1 重新连接适配器</translation>
    </message>
    <message>
        <source>Switch %1 off while it is changed (COB-ID bit 31 = 1: PDO not valid)</source>
        <translation>修改期间先关闭 %1（COB-ID 位 31 = 1：PDO 无效）</translation>
    </message>
    <message>
        <source>When the message is sent: type %1 (transmission type)</source>
        <translation>报文何时发送：类型 %1（传输类型）</translation>
    </message>
    <message>
        <source>Minimum gap between two messages: %1 ms (inhibit time, 100 µs units)</source>
        <translation>两笔报文之间的最短间隔：%1 ms（禁止时间，单位 100 µs）</translation>
    </message>
    <message>
        <source>No minimum gap between two messages (inhibit time = 0)</source>
        <translation>两笔报文之间不设最短间隔（禁止时间 = 0）</translation>
    </message>
    <message>
        <source>Send at least every %1 ms (event timer)</source>
        <translation>至少每 %1 ms 发送一次（事件计时器）</translation>
    </message>
    <message>
        <source>No timer: sent only on its trigger (event timer = 0)</source>
        <translation>不使用计时器：仅在触发时发送（事件计时器 = 0）</translation>
    </message>
    <message>
        <source>Empty the list of mapped objects so it may be rewritten (mapping sub-index 0 = 0)</source>
        <translation>清空映射对象清单以便重新写入（映射子索引 0 = 0）</translation>
    </message>
    <message>
        <source>Object %1 of the message: %2, %3 bits (mapping entry %4)</source>
        <translation>报文的第 %1 个对象：%2，%3 位（映射项目 %4）</translation>
    </message>
    <message>
        <source>Activate the %1 mapped objects (mapping sub-index 0 = number of entries)</source>
        <translation>启用这 %1 个映射对象（映射子索引 0 = 项目数）</translation>
    </message>
    <message>
        <source>Switch %1 on again with CAN-ID %2h (COB-ID bit 31 = 0)</source>
        <translation>以 CAN-ID %2h 重新打开 %1（COB-ID 位 31 = 0）</translation>
    </message>
    <message>
        <source>Map %1 of node %2</source>
        <translation>映射节点 %2 的 %1</translation>
    </message>
    <message>
        <source>node %1 %2: %3; nothing would be sent</source>
        <translation>节点 %1 %2：%3；不会发送任何内容</translation>
    </message>
    <message>
        <source>node %1 %2: %3; nothing was sent</source>
        <translation>节点 %1 %2：%3；未发送任何内容</translation>
    </message>
    <message>
        <source>Stop process data so the PDO can be changed (NMT enter pre-operational, CiA 301 §7.3.2)</source>
        <translation>停止过程数据，以便修改 PDO（NMT 进入预操作状态，CiA 301 §7.3.2）</translation>
    </message>
    <message>
        <source>Check: the COB-ID reads back as written</source>
        <translation>确认：读回的 COB-ID 与写入值相同</translation>
    </message>
    <message>
        <source>Check: the transmission type reads back as written</source>
        <translation>确认：读回的传输类型与写入值相同</translation>
    </message>
    <message>
        <source>Check: the inhibit time reads back as written</source>
        <translation>确认：读回的禁止时间与写入值相同</translation>
    </message>
    <message>
        <source>Check: the event timer reads back as written</source>
        <translation>确认：读回的事件计时器与写入值相同</translation>
    </message>
    <message>
        <source>Check: the number of mapped objects reads back as written</source>
        <translation>确认：读回的映射对象数与写入值相同</translation>
    </message>
    <message>
        <source>Check: mapping entry %1 reads back as written</source>
        <translation>确认：读回的映射项目 %1 与写入值相同</translation>
    </message>
    <message>
        <source>reading the current %1: %2</source>
        <translation>读取当前的 %1：%2</translation>
    </message>
    <message>
        <source>%1 failed: %2; previous mapping restored</source>
        <translation>%1 失败：%2；已恢复先前的映射</translation>
    </message>
    <message>
        <source>%1 failed: %2; restoring the previous mapping failed too: %3</source>
        <translation>%1 失败：%2；恢复先前的映射也失败：%3</translation>
    </message>
    <message>
        <source>%1 failed: %2</source>
        <translation>%1 失败：%2</translation>
    </message>
    <message>
        <source>COB-ID invalid</source>
        <translation>COB-ID 设为无效</translation>
    </message>
    <message>
        <source>COB-ID valid</source>
        <translation>COB-ID 设为有效</translation>
    </message>
    <message>
        <source>transmission type</source>
        <translation>传输类型</translation>
    </message>
    <message>
        <source>inhibit time</source>
        <translation>禁止时间</translation>
    </message>
    <message>
        <source>event timer</source>
        <translation>事件计时器</translation>
    </message>
    <message>
        <source>mapping sub0 = 0</source>
        <translation>映射 sub0 = 0</translation>
    </message>
    <message>
        <source>mapping entry %1</source>
        <translation>映射项目 %1</translation>
    </message>
    <message>
        <source>mapping sub0 = %1</source>
        <translation>映射 sub0 = %1</translation>
    </message>
    <message>
        <source>COB-ID reads back as %1</source>
        <translation>读回的 COB-ID 为 %1</translation>
    </message>
    <message>
        <source>transmission type reads back as %1</source>
        <translation>读回的传输类型为 %1</translation>
    </message>
    <message>
        <source>the mapping reads back differently (%1 entries)</source>
        <translation>读回的映射不同（%1 个项目）</translation>
    </message>
    <message>
        <source>inhibit time reads back differently</source>
        <translation>读回的禁止时间不同</translation>
    </message>
    <message>
        <source>event timer reads back differently</source>
        <translation>读回的事件计时器不同</translation>
    </message>
    <message>
        <source>verify</source>
        <translation>验证</translation>
    </message>
    <message>
        <source>verify: %1</source>
        <translation>验证：%1</translation>
    </message>
    <message>
        <source>read-back failed: %1</source>
        <translation>读回失败：%1</translation>
    </message>
    <message>
        <source>the unconfigured device</source>
        <translation>未设置节点 ID 的设备</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>Reopen the adapter at %1, the device&apos;s new bit rate</source>
        <translation>以设备的新波特率 %1 重新打开适配器</translation>
    </message>
    <message>
        <source>node-ID %1 is not 1-127</source>
        <translation>节点 ID %1 不在 1–127 之间</translation>
    </message>
    <message>
        <source>the new node-ID must be 1-127</source>
        <translation>新的节点 ID 必须在 1–127 之间</translation>
    </message>
    <message>
        <source>node %1 already has this node-ID</source>
        <translation>节点 %1 已经是这个节点 ID</translation>
    </message>
    <message>
        <source>%1 allows node-IDs %2-%3 only</source>
        <translation>%1 只允许节点 ID %2–%3</translation>
    </message>
    <message>
        <source>Change node-ID %1 → %2</source>
        <translation>更改节点 ID %1 → %2</translation>
    </message>
    <message>
        <source>Pick this one device by its identity so only it listens to the next commands (LSS switch state selective)</source>
        <translation>按识别数据选中这一台设备，让接下来的命令只有它接收（LSS 选择性切换状态）</translation>
    </message>
    <message>
        <source>Give it node-ID %1; not used yet (LSS configure node-ID)</source>
        <translation>设置节点 ID 为 %1；尚未生效（LSS 设置节点 ID）</translation>
    </message>
    <message>
        <source>Make the device keep the new node-ID after power-off (LSS store configuration)</source>
        <translation>让设备在断电后保留新的节点 ID（LSS 保存设置）</translation>
    </message>
    <message>
        <source>End the setting mode (LSS switch state global: waiting)</source>
        <translation>结束设置模式（LSS 全域切换状态：等待）</translation>
    </message>
    <message>
        <source>Restart its communication so it uses node-ID %1 (NMT reset communication)</source>
        <translation>重置它的通信，使其改用节点 ID %1（NMT 复位通信）</translation>
    </message>
    <message>
        <source>Wait until it reports at node-ID %1 (boot-up / heartbeat)</source>
        <translation>等待它以节点 ID %1 报告（启动报文／心跳）</translation>
    </message>
    <message>
        <source>at once when the setting mode ends (the device starts with its new node-ID)</source>
        <translation>设置模式结束时立即生效（设备以新的节点 ID 启动）</translation>
    </message>
    <message>
        <source>after NMT reset communication (sent by this wizard) or a power cycle</source>
        <translation>在 NMT 复位通信（由本向导发送）或重新上电之后</translation>
    </message>
    <message>
        <source>Look for the device at node-ID %1 (scan). If it is not there: switch it off and on; if it still does not answer, find it with LSS Fastscan / inquiry and set the node-ID again.</source>
        <translation>在节点 ID %1 查找设备（扫描）。若找不到：将它断电再上电；若仍无响应，用 LSS Fastscan／查找找出它，再重新设置节点 ID。</translation>
    </message>
    <message>
        <source>%1 has no documented node-ID parameter; use LSS</source>
        <translation>%1 没有文档记载的节点 ID 参数；请使用 LSS</translation>
    </message>
    <message>
        <source>this device</source>
        <translation>此设备</translation>
    </message>
    <message>
        <source>an LSS-unconfigured device has no node-ID for SDO; use LSS</source>
        <translation>尚未经 LSS 设置的设备没有可供 SDO 使用的节点 ID；请使用 LSS</translation>
    </message>
    <message>
        <source>Write the new node-ID %1 into %2 (SDO download)</source>
        <translation>将新的节点 ID %1 写入 %2（SDO 下载）</translation>
    </message>
    <message>
        <source>Write the new node-ID %1 into %2 [object inferred] (SDO download)</source>
        <translation>将新的节点 ID %1 写入 %2 [对象为推定]（SDO 下载）</translation>
    </message>
    <message>
        <source>Save the parameters so the node-ID survives power-off (store parameters, 1010h &quot;save&quot;)</source>
        <translation>保存参数，让节点 ID 在断电后仍保留（保存参数，1010h &quot;save&quot;）</translation>
    </message>
    <message>
        <source>Restart the device so it takes node-ID %1 (NMT reset node)</source>
        <translation>重置设备，使其采用节点 ID %1（NMT 复位节点）</translation>
    </message>
    <message>
        <source>after a power cycle (%1). The wizard also sends NMT reset node, which many drives accept; if the drive does not come back, switch it off and on while the wizard waits.</source>
        <translation>在重新上电之后（%1）。向导也会发送 NMT 复位节点，许多驱动器接受此命令；若驱动器没有回来，请在向导等待时将它断电再上电。</translation>
    </message>
    <message>
        <source>after NMT reset node (sent by this wizard) or a power cycle (%1)</source>
        <translation>在 NMT 复位节点（由本向导发送）或重新上电之后（%1）</translation>
    </message>
    <message>
        <source>Switch the drive off and on and look for it at node-ID %1, then at %2. If it answers at %2, the change is stored; if it answers at %1, write %3 again or use LSS.</source>
        <translation>将驱动器断电再上电，先在节点 ID %1、再在 %2 查找它。若在 %2 响应，更改已保存；若在 %1 响应，请重新写入 %3 或改用 LSS。</translation>
    </message>
    <message>
        <source>choose the new bit rate</source>
        <translation>请选择新的波特率</translation>
    </message>
    <message>
        <source>the bus already runs at %1</source>
        <translation>总线已经以 %1 运行</translation>
    </message>
    <message>
        <source>give the device a node-ID first; then change its bit rate</source>
        <translation>请先给设备节点 ID，再更改它的波特率</translation>
    </message>
    <message>
        <source>Change bit rate of node %1: %2 → %3</source>
        <translation>更改节点 %1 的波特率：%2 → %3</translation>
    </message>
    <message>
        <source>Find node %1 at %2</source>
        <translation>以 %2 查找节点 %1</translation>
    </message>
    <message>
        <source>%1 is not in the LSS bit-rate table (CiA 305 Table 1)</source>
        <translation>%1 不在 LSS 波特率表中（CiA 305 表 1）</translation>
    </message>
    <message>
        <source>Pick this one device by its identity so only it listens (LSS switch state selective)</source>
        <translation>按识别数据选中这一台设备，让只有它接收（LSS 选择性切换状态）</translation>
    </message>
    <message>
        <source>Give it the new bit rate %1; not used yet (LSS configure bit timing)</source>
        <translation>设置新波特率 %1；尚未生效（LSS 设置位定时）</translation>
    </message>
    <message>
        <source>Make it keep the new bit rate after power-off (LSS store configuration)</source>
        <translation>让它在断电后保留新波特率（LSS 保存设置）</translation>
    </message>
    <message>
        <source>Switch to the new bit rate now; it goes silent on this bus (LSS activate bit timing)</source>
        <translation>立即切换到新波特率；它在这条总线上将不再收发（LSS 激活位定时）</translation>
    </message>
    <message>
        <source>at once with LSS activate bit timing (and at every power-on after the store)</source>
        <translation>在 LSS 激活位定时时立即生效（保存后每次上电亦然）</translation>
    </message>
    <message>
        <source>%1 has no documented bit-rate parameter; use LSS</source>
        <translation>%1 没有文档记载的波特率参数；请使用 LSS</translation>
    </message>
    <message>
        <source>%1 cannot be set to %2</source>
        <translation>%1 无法设为 %2</translation>
    </message>
    <message>
        <source>Write %1 = %2h: bit rate %3 (SDO download)</source>
        <translation>写入 %1 = %2h：波特率 %3（SDO 下载）</translation>
    </message>
    <message>
        <source>Save the parameters (store parameters, 1010h &quot;save&quot;)</source>
        <translation>保存参数（保存参数，1010h &quot;save&quot;）</translation>
    </message>
    <message>
        <source>Restart the device so it runs at %1; it goes silent on this bus (NMT reset node)</source>
        <translation>重置设备，使其以 %1 运行；它在这条总线上将不再收发（NMT 复位节点）</translation>
    </message>
    <message>
        <source>Let the reset leave the adapter and the device restart before reconnecting</source>
        <translation>重新连接前，先让重置命令发送、设备完成重新启动</translation>
    </message>
    <message>
        <source>after a power cycle (%1); the wizard also sends NMT reset node</source>
        <translation>在重新上电之后（%1）；向导也会发送 NMT 复位节点</translation>
    </message>
    <message>
        <source>after NMT reset node (%1)</source>
        <translation>在 NMT 复位节点之后（%1）</translation>
    </message>
    <message>
        <source>Ask it to announce itself at the new bit rate (NMT reset communication)</source>
        <translation>请它以新波特率重新报到（NMT 复位通信）</translation>
    </message>
    <message>
        <source>Wait until node %1 reports at %2 (boot-up / heartbeat)</source>
        <translation>等待节点 %1 以 %2 报告（启动报文／心跳）</translation>
    </message>
    <message>
        <source>Reconnect at %1 (the old rate) and scan: if node %2 is there, the change did not take effect — switch it off and on and try again at %3. If it answers at neither rate, try the other standard rates, or use LSS with this device alone on the bus.</source>
        <translation>以 %1（旧波特率）重新连接并扫描：若节点 %2 仍在，表示更改未生效——将它断电再上电，再以 %3 尝试。若两种波特率都没有响应，请试试其他标准波特率，或让总线上只剩这台设备再使用 LSS。</translation>
    </message>
    <message>
        <source>cannot read the bit-rate parameter: %1</source>
        <translation>无法读取波特率参数：%1</translation>
    </message>
    <message>
        <source>cannot read the identity (1018h) that LSS needs to pick this device: %1</source>
        <translation>无法读取 LSS 选中此设备所需的识别数据（1018h）：%1</translation>
    </message>
    <message>
        <source>Put back what was changed</source>
        <translation>恢复已更改的设置</translation>
    </message>
    <message>
        <source>Put the old node-ID %1 back (LSS configure node-ID)</source>
        <translation>恢复旧的节点 ID %1（LSS 设置节点 ID）</translation>
    </message>
    <message>
        <source>Put the old bit rate %1 back (LSS configure bit timing)</source>
        <translation>恢复旧波特率 %1（LSS 设置位定时）</translation>
    </message>
    <message>
        <source>Store the old setting again (LSS store configuration)</source>
        <translation>再次保存旧设置（LSS 保存设置）</translation>
    </message>
    <message>
        <source>Write the old value back</source>
        <translation>写回旧值</translation>
    </message>
    <message>
        <source>Save the old value again</source>
        <translation>再次保存旧值</translation>
    </message>
    <message>
        <source>step %1: %2</source>
        <translation>第 %1 步：%2</translation>
    </message>
    <message>
        <source>No device answered LSS with this identity. Check that the drive supports LSS (CiA 305); if not, use its own parameter (vendor method) or the vendor&apos;s tool.</source>
        <translation>没有设备以此识别数据响应 LSS。请确认驱动器支持 LSS（CiA 305）；若不支持，请改用它自己的参数（厂商方式）或厂商的工具。</translation>
    </message>
    <message>
        <source>The device refused the value. Check that it supports it (its manual&apos;s node-ID range / bit rates).</source>
        <translation>设备拒绝了这个值。请确认它支持此值（见手册的节点 ID 范围／波特率）。</translation>
    </message>
    <message>
        <source>The device could not save the setting, so it would be lost at power-off. Check that it supports LSS store (some keep the setting only until power-off); try its own parameter instead.</source>
        <translation>设备无法保存设置，断电后设置会丢失。请确认它支持 LSS 保存（有些设备只保留到断电为止）；请改用它自己的参数。</translation>
    </message>
    <message>
        <source>Check that %1 is powered and answers at this node-ID, that the parameter can be written now (some drives refuse parameter writes while the servo is on or in another control mode) and that the value is in range.</source>
        <translation>请确认%1已上电并以此节点 ID 响应、此时参数可以写入（有些驱动器在伺服启动中或其他控制模式下会拒绝写入参数），且数值在范围内。</translation>
    </message>
    <message>
        <source>Check the connection to %1 and try again.</source>
        <translation>请检查与%1的连接后再试一次。</translation>
    </message>
    <message>
        <source>Put back: %1.</source>
        <translation>已恢复：%1。</translation>
    </message>
    <message>
        <source>Could not put everything back (%1: %2).</source>
        <translation>无法全部恢复（%1：%2）。</translation>
    </message>
    <message>
        <source>Delta ASDA-A2 manual §1.3.1, P3-00 (&quot;●&quot;: after power cycle)</source>
        <translation>Delta ASDA-A2 手册 §1.3.1，P3-00（“●”：重新上电后生效）</translation>
    </message>
    <message>
        <source>Delta ASDA-A2 manual §1.3.1, P3-01 digit Z</source>
        <translation>Delta ASDA-A2 手册 §1.3.1，P3-01 第 Z 位</translation>
    </message>
    <message>
        <source>AIMOTOR manual, CAN settings (H0C-00; object 200Ch:01 inferred)</source>
        <translation>AIMOTOR 手册，CAN 设置（H0C-00；对象 200Ch:01 为推定）</translation>
    </message>
    <message>
        <source>DEXMART DEV tutorial §8.7 (parameter 09-19, DEV Rev A only)</source>
        <translation>DEXMART DEV 教学 §8.7（参数 09-19，仅限 DEV Rev A）</translation>
    </message>
    <message>
        <source>node %1 axis %2</source>
        <translation>节点 %1 轴 %2</translation>
    </message>
    <message>
        <source>%1 went to %2 instead of %3: statusword 0x%4</source>
        <translation>%1 进入了%2，而不是%3：状态字 0x%4</translation>
    </message>
    <message>
        <source>%1 did not reach %2 within %3 ms: statusword 0x%4 (%5): %6</source>
        <translation>%1 未在 %3 ms 内到达%2：状态字 0x%4（%5）：%6</translation>
    </message>
    <message>
        <source>missing bit %1 (%2)</source>
        <translation>缺少位 %1（%2）</translation>
    </message>
    <message>
        <source>unexpected bit %1 (%2)</source>
        <translation>多出位 %1（%2）</translation>
    </message>
    <message>
        <source>%1 (bit %2) is on: %3</source>
        <translation>%1（位 %2）为 on：%3</translation>
    </message>
    <message>
        <source>%1 (bit %2) is off: %3</source>
        <translation>%1（位 %2）为 off：%3</translation>
    </message>
    <message>
        <source>%1 (bit %2) is on</source>
        <translation>%1（位 %2）为 on</translation>
    </message>
    <message>
        <source>%1 (bit %2) is off</source>
        <translation>%1（位 %2）为 off</translation>
    </message>
    <message>
        <source>bit 7 low before fault reset</source>
        <translation>故障复位前将位 7 设为低</translation>
    </message>
    <message>
        <source>Disable voltage, enable failed</source>
        <translation>切断电压（使能失败）</translation>
    </message>
    <message>
        <source>%1; drive disabled</source>
        <translation>%1；已解除驱动器使能</translation>
    </message>
    <message>
        <source>%1; disabling the drive failed too: %2</source>
        <translation>%1；解除驱动器使能也失败：%2</translation>
    </message>
    <message>
        <source>%1: modes of operation display %2h shows %3 (%4), not %5 (%6), after %7 ms</source>
        <translation>%1：%7 ms 后，运行模式显示 %2h 为 %3（%4），而不是 %5（%6）</translation>
    </message>
    <message>
        <source>Controlword bit 7 low first: fault reset acts on its rising edge</source>
        <translation>先将控制字位 7 设为低：故障复位在上升沿动作</translation>
    </message>
    <message>
        <source>Clear the fault (Fault reset, CiA 402 transition 15)</source>
        <translation>清除故障（故障复位，CiA 402 转换 15）</translation>
    </message>
    <message>
        <source>Make the drive ready (Shutdown, transition 2)</source>
        <translation>让驱动器就绪（Shutdown，转换 2）</translation>
    </message>
    <message>
        <source>Switch the power stage on, motor not yet energised (Switch on, transition 3)</source>
        <translation>打开功率级，电机尚未通电（Switch on，转换 3）</translation>
    </message>
    <message>
        <source>Energise the motor: it holds position and follows commands (Enable operation, transition 4)</source>
        <translation>电机通电：保持位置并跟随命令（运行使能，转换 4）</translation>
    </message>
    <message>
        <source>Stop following commands, power stage stays on (Disable operation, transition 5)</source>
        <translation>停止跟随命令，功率级保持打开（Disable operation，转换 5）</translation>
    </message>
    <message>
        <source>Remove power from the motor (Disable voltage)</source>
        <translation>切断电机电源（Disable voltage）</translation>
    </message>
    <message>
        <source>Brake on the quick stop ramp (Quick stop)</source>
        <translation>按快速停止斜坡减速（Quick stop）</translation>
    </message>
    <message>
        <source>Statusword must show %1</source>
        <translation>状态字必须显示%1</translation>
    </message>
    <message>
        <source>CiA 402 enable of node %1</source>
        <translation>节点 %1 的 CiA 402 使能</translation>
    </message>
    <message>
        <source>CiA 402 enable of node %1 axis %2</source>
        <translation>节点 %1 轴 %2 的 CiA 402 使能</translation>
    </message>
    <message>
        <source>Choose the mode of operation: %1 (6060h)</source>
        <translation>选择运行模式：%1（6060h）</translation>
    </message>
    <message>
        <source>The drive confirms the mode (modes of operation display 6061h)</source>
        <translation>驱动器确认模式（运行模式显示 6061h）</translation>
    </message>
    <message>
        <source>jog velocity must be non-zero and at most %1 units/s</source>
        <translation>点动速度不可为 0，且最多 %1 单位/s</translation>
    </message>
    <message>
        <source>profile velocity must be 1-%1 units/s</source>
        <translation>轮廓速度必须在 1–%1 单位/s 之间</translation>
    </message>
    <message>
        <source>relative move must be non-zero and at most %1 units</source>
        <translation>相对移动量不可为 0，且最多 %1 单位</translation>
    </message>
    <message>
        <source>acceleration and deceleration must be above 0</source>
        <translation>加速度与减速度必须大于 0</translation>
    </message>
    <message>
        <source>test move time must be 1-%1 ms</source>
        <translation>测试运动时间必须在 1–%1 ms 之间</translation>
    </message>
    <message>
        <source>watchdog must be at least 50 ms</source>
        <translation>看门狗时间至少须 50 ms</translation>
    </message>
    <message>
        <source>a test move is already running</source>
        <translation>已有测试运动在运行中</translation>
    </message>
    <message>
        <source>%1 (profile acceleration)</source>
        <translation>%1（轮廓加速度）</translation>
    </message>
    <message>
        <source>%1 (profile deceleration)</source>
        <translation>%1（轮廓减速度）</translation>
    </message>
    <message>
        <source>Enable operation, halt off</source>
        <translation>运行使能，解除暂停（halt）</translation>
    </message>
    <message>
        <source>%1 (target velocity)</source>
        <translation>%1（目标速度）</translation>
    </message>
    <message>
        <source>%1 (profile velocity)</source>
        <translation>%1（轮廓速度）</translation>
    </message>
    <message>
        <source>%1 (target position, relative)</source>
        <translation>%1（目标位置，相对）</translation>
    </message>
    <message>
        <source>Enable operation, relative, new set-point low</source>
        <translation>运行使能，相对，新设置点为低</translation>
    </message>
    <message>
        <source>New set-point (bit 4 rising), relative (bit 6)</source>
        <translation>新设置点（位 4 上升沿），相对（位 6）</translation>
    </message>
    <message>
        <source>test move set-up failed: %1</source>
        <translation>测试运动设置失败：%1</translation>
    </message>
    <message>
        <source>%1 is in %2, not Operation enabled: enable the drive before a test move</source>
        <translation>%1 处于%2，不是运行使能：测试运动前请先使能驱动器</translation>
    </message>
    <message>
        <source>cannot set the mode for the test move: %1</source>
        <translation>无法设置测试运动的模式：%1</translation>
    </message>
    <message>
        <source>the drive stopped answering during the test move (%1)</source>
        <translation>测试运动中驱动器停止响应（%1）</translation>
    </message>
    <message>
        <source>the drive faulted during the test move (statusword 0x%1)</source>
        <translation>测试运动中驱动器发生故障（状态字 0x%1）</translation>
    </message>
    <message>
        <source>the drive left Operation enabled during the test move (now %1)</source>
        <translation>测试运动中驱动器离开了运行使能（现在为%1）</translation>
    </message>
    <message>
        <source>position read failed during the test move: %1</source>
        <translation>测试运动中读取位置失败：%1</translation>
    </message>
    <message>
        <source>velocity read failed during the test move: %1</source>
        <translation>测试运动中读取速度失败：%1</translation>
    </message>
    <message>
        <source>hold-to-run released (no signal for %1 ms)</source>
        <translation>已放开按住运行（%1 ms 没有信号）</translation>
    </message>
    <message>
        <source>time limit of %1 ms reached</source>
        <translation>已达 %1 ms 的时间上限</translation>
    </message>
    <message>
        <source>Halt: stop the test move on the deceleration ramp</source>
        <translation>暂停（Halt）：按减速斜坡停止测试运动</translation>
    </message>
    <message>
        <source>halt failed: %1</source>
        <translation>暂停失败：%1</translation>
    </message>
    <message>
        <source>velocity read failed while stopping: %1</source>
        <translation>停止时读取速度失败：%1</translation>
    </message>
    <message>
        <source>the motor did not stop within %1 ms of the halt</source>
        <translation>暂停后 %1 ms 内电机未停止</translation>
    </message>
    <message>
        <source>%1: %2h = 0 (target velocity)</source>
        <translation>%1：%2h = 0（目标速度）</translation>
    </message>
    <message>
        <source>target velocity 0 failed: %1</source>
        <translation>目标速度设为 0 失败：%1</translation>
    </message>
    <message>
        <source>Quick stop, test move failed</source>
        <translation>快速停止（测试运动失败）</translation>
    </message>
    <message>
        <source>Disable voltage, test move failed</source>
        <translation>切断电压（测试运动失败）</translation>
    </message>
    <message>
        <source>node-ID %1 is outside 1-127</source>
        <translation>节点 ID %1 不在 1–127 之间</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <source>node %1 read %2: cancelled</source>
        <translation>节点 %1 读取 %2：已取消</translation>
    </message>
    <message>
        <source>node %1 write %2: cancelled</source>
        <translation>节点 %1 写入 %2：已取消</translation>
    </message>
    <message>
        <source>the server answered for %1</source>
        <translation>伺服端响应的是 %1</translation>
    </message>
    <message>
        <source>toggle bit not alternated in an upload segment</source>
        <translation>上传分段的切换位没有交替</translation>
    </message>
    <message>
        <source>the server sent %1 bytes, more than the %2 it announced</source>
        <translation>伺服端发送 %1 字节，多于声明的 %2</translation>
    </message>
    <message>
        <source>the server sent %1 bytes of the %2 it announced</source>
        <translation>伺服端只发送声明 %2 字节中的 %1</translation>
    </message>
    <message>
        <source>toggle bit not alternated in a download segment response</source>
        <translation>下载分段响应的切换位没有交替</translation>
    </message>
    <message>
        <source>unexpected %1 from the server</source>
        <translation>伺服端送来非预期的 %1</translation>
    </message>
    <message>
        <source>block end says %1 unused bytes</source>
        <translation>块结束标示 %1 个未使用字节</translation>
    </message>
    <message>
        <source>CRC error: the server sent %1, the data gives %2</source>
        <translation>CRC 错误：伺服端发送 %1，数据计算为 %2</translation>
    </message>
    <message>
        <source>invalid block size %1</source>
        <translation>无效的块大小 %1</translation>
    </message>
    <message>
        <source>acknowledged segment %1 of %2 sent</source>
        <translation>已确认 %2 个已发送分段中的第 %1 个</translation>
    </message>
    <message>
        <source>node %1 did not answer read of %2 within %3 ms (SDO protocol timed out, 0x05040000)</source>
        <translation>节点 %1 未在 %3 ms 内响应 %2 的读取（SDO 协议超时，0x05040000）</translation>
    </message>
    <message>
        <source>node %1 did not answer write of %2 within %3 ms (SDO protocol timed out, 0x05040000)</source>
        <translation>节点 %1 未在 %3 ms 内响应 %2 的写入（SDO 协议超时，0x05040000）</translation>
    </message>
    <message>
        <source>node %1 aborted %2: %3</source>
        <translation>节点 %1 中止了 %2：%3</translation>
    </message>
    <message>
        <source>node %1 read %2: %3; transfer aborted with 0x%4</source>
        <translation>节点 %1 读取 %2：%3；传输以 0x%4 中止</translation>
    </message>
    <message>
        <source>node %1 write %2: %3; transfer aborted with 0x%4</source>
        <translation>节点 %1 写入 %2：%3；传输以 0x%4 中止</translation>
    </message>
    <message>
        <source>node %1 read %2: %3</source>
        <translation>节点 %1 读取 %2：%3</translation>
    </message>
    <message>
        <source>node %1 write %2: %3</source>
        <translation>节点 %1 写入 %2：%3</translation>
    </message>
    <message>
        <source>not supported or out of range</source>
        <translation>不支持或超出范围</translation>
    </message>
    <message>
        <source>manufacturer-specific error</source>
        <translation>制造商自定义错误</translation>
    </message>
    <message>
        <source>error %1</source>
        <translation>错误 %1</translation>
    </message>
    <message>
        <source>LSS %1 refused by the slave: %2 (error code %3)</source>
        <translation>从站拒绝 LSS %1：%2（错误码 %3）</translation>
    </message>
    <message>
        <source>no slave with that identity answered switch state selective</source>
        <translation>没有符合此识别数据的从站响应选择性切换状态</translation>
    </message>
    <message>
        <source>no answer to LSS configure node-ID (is a slave in configuration state?)</source>
        <translation>LSS 设置节点 ID 没有响应（是否有从站处于设置状态？）</translation>
    </message>
    <message>
        <source>configure node-ID</source>
        <translation>设置节点 ID</translation>
    </message>
    <message>
        <source>%1 bit/s is not in the CiA 305 bit timing table</source>
        <translation>%1 bit/s 不在 CiA 305 位定时表中</translation>
    </message>
    <message>
        <source>no answer to LSS configure bit timing (is a slave in configuration state?)</source>
        <translation>LSS 设置位定时没有响应（是否有从站处于设置状态？）</translation>
    </message>
    <message>
        <source>configure bit timing</source>
        <translation>设置位定时</translation>
    </message>
    <message>
        <source>no answer to LSS store configuration (is a slave in configuration state?)</source>
        <translation>LSS 保存设置没有响应（是否有从站处于设置状态？）</translation>
    </message>
    <message>
        <source>store configuration</source>
        <translation>保存设置</translation>
    </message>
    <message>
        <source>no answer to LSS %1 (is a slave in configuration state?)</source>
        <translation>LSS %1 没有响应（是否有从站处于设置状态？）</translation>
    </message>
    <message>
        <source>this run cannot reopen the adapter; reconnect at %1 bit/s by hand</source>
        <translation>此次运行无法重新打开适配器；请手动以 %1 bit/s 重新连接</translation>
    </message>
    <message>
        <source>could not reopen the adapter</source>
        <translation>无法重新打开适配器</translation>
    </message>
    <message>
        <source>connected at %1 bit/s</source>
        <translation>已以 %1 bit/s 连接</translation>
    </message>
    <message>
        <source>step %1 (%2): cancelled</source>
        <translation>第 %1 步（%2）：已取消</translation>
    </message>
    <message>
        <source>step %1 (%2): %3</source>
        <translation>第 %1 步（%2）：%3</translation>
    </message>
    <message>
        <source>written</source>
        <translation>已写入</translation>
    </message>
    <message>
        <source>read %1</source>
        <translation>读到 %1</translation>
    </message>
    <message>
        <source>read %1 as expected</source>
        <translation>读到 %1，符合预期</translation>
    </message>
    <message>
        <source>node %1 %2 reads %3, expected %4</source>
        <translation>节点 %1 %2 读到 %3，预期为 %4</translation>
    </message>
    <message>
        <source>node %1 %2 reads %3, expected %4 under mask %5</source>
        <translation>节点 %1 %2 读到 %3，预期为 %4（掩码 %5）</translation>
    </message>
    <message>
        <source>sent</source>
        <translation>已发送</translation>
    </message>
    <message>
        <source>the device confirmed</source>
        <translation>设备已确认</translation>
    </message>
    <message>
        <source>the device stored it</source>
        <translation>设备已保存</translation>
    </message>
    <message>
        <source>waited %1 ms</source>
        <translation>已等待 %1 ms</translation>
    </message>
    <message>
        <source>node %1 sent no boot-up within %2 ms</source>
        <translation>节点 %1 未在 %2 ms 内发送启动报文</translation>
    </message>
    <message>
        <source>node %1 sent no boot-up or heartbeat within %2 ms</source>
        <translation>节点 %1 未在 %2 ms 内发送启动报文或心跳</translation>
    </message>
    <message>
        <source>unknown step</source>
        <translation>未知的步骤</translation>
    </message>
    <message>
        <source>node %1 booted</source>
        <translation>节点 %1 已上线</translation>
    </message>
    <message>
        <source>node %1 is %2</source>
        <translation>节点 %1 为%2</translation>
    </message>
    <message>
        <source>node-ID %1 is outside 1-127 (0 = all nodes)</source>
        <translation>节点 ID %1 不在 1–127 之间（0 = 所有节点）</translation>
    </message>
    <message>
        <source>%1 (not writable)</source>
        <translation>%1（不可写入）</translation>
    </message>
    <message>
        <source>command object, not configuration</source>
        <translation>命令对象，不是设置值</translation>
    </message>
    <message>
        <source>unchanged (%1)</source>
        <translation>未更改（%1）</translation>
    </message>
    <message>
        <source>node %1 %2: not in the dictionary</source>
        <translation>节点 %1 %2：不在对象字典中</translation>
    </message>
    <message>
        <source>COB-ID invalid (%1)</source>
        <translation>COB-ID 设为无效（%1）</translation>
    </message>
    <message>
        <source>COB-ID valid (%1)</source>
        <translation>COB-ID 设为有效（%1）</translation>
    </message>
    <message>
        <source>transmission type (%1)</source>
        <translation>传输类型（%1）</translation>
    </message>
    <message>
        <source>inhibit time (%1)</source>
        <translation>禁止时间（%1）</translation>
    </message>
    <message>
        <source>event timer (%1)</source>
        <translation>事件计时器（%1）</translation>
    </message>
    <message>
        <source>mapping sub0 = 0 (%1)</source>
        <translation>映射 sub0 = 0（%1）</translation>
    </message>
    <message>
        <source>mapping entry %1 (%2)</source>
        <translation>映射项目 %1（%2）</translation>
    </message>
    <message>
        <source>Error reset or no error</source>
        <translation>错误重置或无错误</translation>
    </message>
    <message>
        <source>Generic error</source>
        <translation>一般错误</translation>
    </message>
    <message>
        <source>Continuous over-current</source>
        <translation>持续过电流</translation>
    </message>
    <message>
        <source>Short circuit / earth leakage</source>
        <translation>短路／接地漏电</translation>
    </message>
    <message>
        <source>Mains over-voltage</source>
        <translation>主电源过电压</translation>
    </message>
    <message>
        <source>Mains under-voltage</source>
        <translation>主电源欠电压</translation>
    </message>
    <message>
        <source>DC link over-voltage</source>
        <translation>直流母线过电压</translation>
    </message>
    <message>
        <source>DC link under-voltage</source>
        <translation>直流母线欠电压</translation>
    </message>
    <message>
        <source>Excess temperature device</source>
        <translation>设备温度过高</translation>
    </message>
    <message>
        <source>Excess temperature drive</source>
        <translation>驱动器温度过高</translation>
    </message>
    <message>
        <source>Data storage error (EEPROM)</source>
        <translation>数据保存错误（EEPROM）</translation>
    </message>
    <message>
        <source>Internal software error</source>
        <translation>内部软件错误</translation>
    </message>
    <message>
        <source>Motor blocked</source>
        <translation>电机堵转</translation>
    </message>
    <message>
        <source>Incremental sensor 1 fault</source>
        <translation>增量式传感器 1 故障</translation>
    </message>
    <message>
        <source>CAN overrun (objects lost)</source>
        <translation>CAN 溢出（对象丢失）</translation>
    </message>
    <message>
        <source>CAN in error passive mode</source>
        <translation>CAN 处于错误被动模式</translation>
    </message>
    <message>
        <source>Life guard error or heartbeat error</source>
        <translation>节点保护错误或心跳错误</translation>
    </message>
    <message>
        <source>Recovered from bus off</source>
        <translation>已从总线关闭恢复</translation>
    </message>
    <message>
        <source>CAN-ID collision</source>
        <translation>CAN-ID 冲突</translation>
    </message>
    <message>
        <source>PDO not processed due to length error</source>
        <translation>PDO 因长度错误未处理</translation>
    </message>
    <message>
        <source>PDO length exceeded</source>
        <translation>PDO 长度超出</translation>
    </message>
    <message>
        <source>DAM MPDO not processed, destination object not available</source>
        <translation>DAM MPDO 未处理，目标对象不存在</translation>
    </message>
    <message>
        <source>Unexpected SYNC data length</source>
        <translation>SYNC 数据长度不符</translation>
    </message>
    <message>
        <source>RPDO timeout</source>
        <translation>RPDO 超时</translation>
    </message>
    <message>
        <source>Following error</source>
        <translation>追随误差</translation>
    </message>
    <message>
        <source>Reference limit</source>
        <translation>参考极限</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>电流</translation>
    </message>
    <message>
        <source>Current, device input side</source>
        <translation>电流（设备输入侧）</translation>
    </message>
    <message>
        <source>Current inside the device</source>
        <translation>设备内部电流</translation>
    </message>
    <message>
        <source>Current, device output side</source>
        <translation>电流（设备输出侧）</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>电压</translation>
    </message>
    <message>
        <source>Mains voltage</source>
        <translation>主电源电压</translation>
    </message>
    <message>
        <source>Voltage inside the device</source>
        <translation>设备内部电压</translation>
    </message>
    <message>
        <source>Output voltage</source>
        <translation>输出电压</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <source>Ambient temperature</source>
        <translation>环境温度</translation>
    </message>
    <message>
        <source>Device temperature</source>
        <translation>设备温度</translation>
    </message>
    <message>
        <source>Device hardware</source>
        <translation>设备硬件</translation>
    </message>
    <message>
        <source>Device software</source>
        <translation>设备软件</translation>
    </message>
    <message>
        <source>Internal software</source>
        <translation>内部软件</translation>
    </message>
    <message>
        <source>User software</source>
        <translation>用户软件</translation>
    </message>
    <message>
        <source>Data set</source>
        <translation>数据集</translation>
    </message>
    <message>
        <source>Additional modules</source>
        <translation>附加模块</translation>
    </message>
    <message>
        <source>Monitoring</source>
        <translation>监控</translation>
    </message>
    <message>
        <source>Communication</source>
        <translation>通信</translation>
    </message>
    <message>
        <source>Protocol error</source>
        <translation>协议错误</translation>
    </message>
    <message>
        <source>External error</source>
        <translation>外部错误</translation>
    </message>
    <message>
        <source>Additional functions</source>
        <translation>附加功能</translation>
    </message>
    <message>
        <source>Device specific</source>
        <translation>设备自定义</translation>
    </message>
    <message>
        <source>Unknown error code</source>
        <translation>未知的错误码</translation>
    </message>
    <message>
        <source>Delta: P-parameters written over CAN are saved to EEPROM at once. P3-00 takes effect after a power cycle (marked ●).</source>
        <translation>台达：经 CAN 写入的 P 参数会立即存入 EEPROM。P3-00 须重新上电后才生效（标记 ●）。</translation>
    </message>
    <message>
        <source>AIMOTOR: the manual sets H0C-00 (node-ID) with the RS485 tool; writing it over CAN (200Ch:01) is inferred, save with 1010h and power-cycle. The bit-rate codes of H0C-08 are not documented: use LSS for the bit rate.</source>
        <translation>AIMOTOR：手册以 RS485 工具设置 H0C-00（节点 ID）；经 CAN（200Ch:01）写入是推定的做法，请以 1010h 保存并重新上电。H0C-08 的波特率代码未见于文档：波特率请使用 LSS 设置。</translation>
    </message>
    <message>
        <source>DEXMART DEV: parameter 09-19 sets the node-ID on Rev A only; Rev B/C/D use DIP switch SW2. No bit-rate parameter: use LSS.</source>
        <translation>DEXMART DEV：参数 09-19 仅在 Rev A 上设置节点 ID；Rev B/C/D 使用 DIP 开关 SW2。没有波特率参数：请使用 LSS。</translation>
    </message>
    <message>
        <source>Voltage enabled</source>
        <translation>电压已使能</translation>
    </message>
    <message>
        <source>Remote</source>
        <translation>远程控制（Remote）</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>Target reached</source>
        <translation>已到达目标</translation>
    </message>
    <message>
        <source>Internal limit active</source>
        <translation>内部限制作用中</translation>
    </message>
    <message>
        <source>TPDO%1 node %2: %3</source>
        <translation>TPDO%1 节点 %2：%3</translation>
    </message>
    <message>
        <source>RPDO%1 node %2: %3</source>
        <translation>RPDO%1 节点 %2：%3</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>命令</translation>
    </message>
    <message>
        <source>Command specifier</source>
        <translation>命令标识符</translation>
    </message>
    <message>
        <source>Index</source>
        <translation>索引</translation>
    </message>
    <message>
        <source>Sub-index</source>
        <translation>子索引</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>数据</translation>
    </message>
    <message>
        <source>Data (mapping not known)</source>
        <translation>数据（映射未知）</translation>
    </message>
    <message>
        <source>Abort code</source>
        <translation>中止码</translation>
    </message>
    <message>
        <source>Node-ID</source>
        <translation>节点 ID</translation>
    </message>
    <message>
        <source>0 (all nodes)</source>
        <translation>0（所有节点）</translation>
    </message>
    <message>
        <source>Counter</source>
        <translation>计数器</translation>
    </message>
    <message>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Toggle bit</source>
        <translation>翻转位</translation>
    </message>
    <message>
        <source>Error code</source>
        <translation>错误码</translation>
    </message>
    <message>
        <source>Error register</source>
        <translation>错误寄存器</translation>
    </message>
    <message>
        <source>Manufacturer-specific error field</source>
        <translation>制造商定义错误字段</translation>
    </message>
    <message>
        <source>Vendor alarm</source>
        <translation>厂家报警</translation>
    </message>
    <message>
        <source>Milliseconds after midnight</source>
        <translation>午夜起的毫秒数</translation>
    </message>
    <message>
        <source>Days since 1984-01-01</source>
        <translation>自 1984-01-01 起的天数</translation>
    </message>
    <message>
        <source>Command (CiA 402)</source>
        <translation>命令（CiA 402）</translation>
    </message>
    <message>
        <source>State (CiA 402)</source>
        <translation>状态（CiA 402）</translation>
    </message>
    <message>
        <source>Mode of operation (CiA 402)</source>
        <translation>运行模式（CiA 402）</translation>
    </message>
    <message>
        <source>Bit %1</source>
        <translation>位 %1</translation>
    </message>
    <message>
        <source>set</source>
        <translation>为 1</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>正常</translation>
    </message>
    <message>
        <source>aborted</source>
        <translation>已中止</translation>
    </message>
    <message>
        <source>size mismatch</source>
        <translation>大小不符</translation>
    </message>
    <message>
        <source>crc error</source>
        <translation>CRC 错误</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>Manufacturer-specific mode %1</source>
        <translation>制造商定义模式 %1</translation>
    </message>
    <message>
        <source>Reserved mode %1</source>
        <translation>保留模式 %1</translation>
    </message>
    <message>
        <source>abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <source>0x%1 %2</source>
        <translation>0x%1 %2</translation>
    </message>
    <message>
        <source>SDO %1 node %2</source>
        <translation>SDO %1 节点 %2</translation>
    </message>
    <message>
        <source>SDO %1 node %2 %3</source>
        <translation>SDO %1 节点 %2 %3</translation>
    </message>
    <message>
        <source>SDO %1 node %2 %3, block size %4</source>
        <translation>SDO %1 节点 %2 %3，块大小 %4</translation>
    </message>
    <message>
        <source>SDO %1 node %2 %3, %4 bytes</source>
        <translation>SDO %1 节点 %2 %3，%4 字节</translation>
    </message>
    <message>
        <source>SDO %1 node %2 %3, block size %4, %5 bytes</source>
        <translation>SDO %1 节点 %2 %3，块大小 %4，%5 字节</translation>
    </message>
    <message>
        <source>%1 [%2]</source>
        <translation>%1［%2］</translation>
    </message>
    <message>
        <source>%1 -&gt; read %2 bytes = %3</source>
        <translation>%1 → 已读取 %2 字节 = %3</translation>
    </message>
    <message>
        <source>%1 -&gt; read %2 bytes</source>
        <translation>%1 → 已读取 %2 字节</translation>
    </message>
    <message>
        <source>%1 -&gt; wrote %2 bytes = %3</source>
        <translation>%1 → 已写入 %2 字节 = %3</translation>
    </message>
    <message>
        <source>%1 -&gt; wrote %2 bytes</source>
        <translation>%1 → 已写入 %2 字节</translation>
    </message>
    <message>
        <source>CAN error: %1</source>
        <translation>CAN 错误：%1</translation>
    </message>
    <message>
        <source>Error classes</source>
        <translation>错误类别</translation>
    </message>
    <message>
        <source>Bus state</source>
        <translation>总线状态</translation>
    </message>
    <message>
        <source>Problem</source>
        <translation>问题</translation>
    </message>
    <message>
        <source>TX error counter</source>
        <translation>发送错误计数器</translation>
    </message>
    <message>
        <source>RX error counter</source>
        <translation>接收错误计数器</translation>
    </message>
    <message>
        <source>error active</source>
        <translation>错误主动</translation>
    </message>
    <message>
        <source>error warning</source>
        <translation>错误警告</translation>
    </message>
    <message>
        <source>error passive</source>
        <translation>错误被动</translation>
    </message>
    <message>
        <source>bus-off</source>
        <translation>总线关闭</translation>
    </message>
    <message>
        <source>bus-off (the controller stopped sending after too many errors)</source>
        <translation>总线关闭（错误过多，控制器已停止发送）</translation>
    </message>
    <message>
        <source>controller: %1</source>
        <translation>控制器：%1</translation>
    </message>
    <message>
        <source>TX error passive</source>
        <translation>发送错误被动</translation>
    </message>
    <message>
        <source>RX error passive</source>
        <translation>接收错误被动</translation>
    </message>
    <message>
        <source>TX error warning</source>
        <translation>发送错误警告</translation>
    </message>
    <message>
        <source>RX error warning</source>
        <translation>接收错误警告</translation>
    </message>
    <message>
        <source>RX buffer overflow (frames lost)</source>
        <translation>接收缓冲区溢出（帧丢失）</translation>
    </message>
    <message>
        <source>TX buffer overflow</source>
        <translation>发送缓冲区溢出</translation>
    </message>
    <message>
        <source>back to error active</source>
        <translation>回到错误主动</translation>
    </message>
    <message>
        <source>unspecified</source>
        <translation>未指明</translation>
    </message>
    <message>
        <source>no acknowledge (no other node on the bus, or a different bit rate)</source>
        <translation>没有 ACK 应答（总线上没有其他节点，或波特率不同）</translation>
    </message>
    <message>
        <source>protocol violation</source>
        <translation>协议错误</translation>
    </message>
    <message>
        <source>protocol violation: %1</source>
        <translation>协议错误：%1</translation>
    </message>
    <message>
        <source>protocol violation: %1 in the %2</source>
        <translation>协议错误：%1（位置：%2）</translation>
    </message>
    <message>
        <source>protocol violation in the %1</source>
        <translation>协议错误（位置：%1）</translation>
    </message>
    <message>
        <source>bit error</source>
        <translation>位错误</translation>
    </message>
    <message>
        <source>form error</source>
        <translation>格式错误</translation>
    </message>
    <message>
        <source>stuff error</source>
        <translation>填充错误</translation>
    </message>
    <message>
        <source>could not send a dominant bit</source>
        <translation>无法发送显性位</translation>
    </message>
    <message>
        <source>could not send a recessive bit</source>
        <translation>无法发送隐性位</translation>
    </message>
    <message>
        <source>bus overload</source>
        <translation>总线过载</translation>
    </message>
    <message>
        <source>active error flag</source>
        <translation>主动错误标志</translation>
    </message>
    <message>
        <source>while transmitting</source>
        <translation>发送时</translation>
    </message>
    <message>
        <source>start of frame</source>
        <translation>帧起始（SOF）</translation>
    </message>
    <message>
        <source>identifier bits %1</source>
        <translation>标识符位 %1</translation>
    </message>
    <message>
        <source>SRTR bit</source>
        <translation>SRTR 位</translation>
    </message>
    <message>
        <source>IDE bit</source>
        <translation>IDE 位</translation>
    </message>
    <message>
        <source>RTR bit</source>
        <translation>RTR 位</translation>
    </message>
    <message>
        <source>reserved bit %1</source>
        <translation>保留位 %1</translation>
    </message>
    <message>
        <source>data length code</source>
        <translation>数据长度码（DLC）</translation>
    </message>
    <message>
        <source>data field</source>
        <translation>数据段</translation>
    </message>
    <message>
        <source>CRC sequence</source>
        <translation>CRC 序列</translation>
    </message>
    <message>
        <source>CRC delimiter</source>
        <translation>CRC 界定符</translation>
    </message>
    <message>
        <source>ACK slot</source>
        <translation>ACK 槽</translation>
    </message>
    <message>
        <source>ACK delimiter</source>
        <translation>ACK 界定符</translation>
    </message>
    <message>
        <source>end of frame</source>
        <translation>帧结束（EOF）</translation>
    </message>
    <message>
        <source>intermission</source>
        <translation>帧间隔</translation>
    </message>
    <message>
        <source>transceiver problem (status 0x%1)</source>
        <translation>收发器异常（状态 0x%1）</translation>
    </message>
    <message>
        <source>lost arbitration at bit %1</source>
        <translation>仲裁失败（第 %1 位）</translation>
    </message>
    <message>
        <source>lost arbitration</source>
        <translation>仲裁失败</translation>
    </message>
    <message>
        <source>transmit timeout</source>
        <translation>发送超时</translation>
    </message>
    <message>
        <source>bus error</source>
        <translation>总线错误</translation>
    </message>
    <message>
        <source>controller restarted</source>
        <translation>控制器已重新启动</translation>
    </message>
    <message>
        <source>error counters TX %1, RX %2</source>
        <translation>错误计数器 TX %1，RX %2</translation>
    </message>
    <message>
        <source>error frame (class %1h)</source>
        <translation>错误帧（类别 %1h）</translation>
    </message>
    <message>
        <source>Switch state global</source>
        <translation>全域切换状态</translation>
    </message>
    <message>
        <source>Switch state selective: vendor-ID</source>
        <translation>选择性切换状态：厂商 ID</translation>
    </message>
    <message>
        <source>Switch state selective: product code</source>
        <translation>选择性切换状态：产品代码</translation>
    </message>
    <message>
        <source>Switch state selective: revision number</source>
        <translation>选择性切换状态：版本号</translation>
    </message>
    <message>
        <source>Switch state selective: serial number</source>
        <translation>选择性切换状态：序列号</translation>
    </message>
    <message>
        <source>Switch state selective response</source>
        <translation>选择性切换状态响应</translation>
    </message>
    <message>
        <source>Configure node-ID</source>
        <translation>设置节点 ID</translation>
    </message>
    <message>
        <source>Configure node-ID response</source>
        <translation>设置节点 ID 响应</translation>
    </message>
    <message>
        <source>Configure bit timing</source>
        <translation>设置位定时</translation>
    </message>
    <message>
        <source>Configure bit timing response</source>
        <translation>设置位定时响应</translation>
    </message>
    <message>
        <source>Activate bit timing</source>
        <translation>激活位定时</translation>
    </message>
    <message>
        <source>Store configuration</source>
        <translation>保存设置</translation>
    </message>
    <message>
        <source>Store configuration response</source>
        <translation>保存设置响应</translation>
    </message>
    <message>
        <source>Inquire vendor-ID</source>
        <translation>查询厂商 ID</translation>
    </message>
    <message>
        <source>Vendor-ID</source>
        <translation>厂商 ID</translation>
    </message>
    <message>
        <source>Inquire product code</source>
        <translation>查询产品代码</translation>
    </message>
    <message>
        <source>Product code</source>
        <translation>产品代码</translation>
    </message>
    <message>
        <source>Inquire revision number</source>
        <translation>查询版本号</translation>
    </message>
    <message>
        <source>Revision number</source>
        <translation>版本号</translation>
    </message>
    <message>
        <source>Inquire serial number</source>
        <translation>查询序列号</translation>
    </message>
    <message>
        <source>Serial number</source>
        <translation>序列号</translation>
    </message>
    <message>
        <source>Inquire node-ID</source>
        <translation>查询节点 ID</translation>
    </message>
    <message>
        <source>Identify remote slave: vendor-ID</source>
        <translation>识别远程从站：厂商 ID</translation>
    </message>
    <message>
        <source>Identify remote slave: product code</source>
        <translation>识别远程从站：产品代码</translation>
    </message>
    <message>
        <source>Identify remote slave: revision low</source>
        <translation>识别远程从站：版本号下限</translation>
    </message>
    <message>
        <source>Identify remote slave: revision high</source>
        <translation>识别远程从站：版本号上限</translation>
    </message>
    <message>
        <source>Identify remote slave: serial low</source>
        <translation>识别远程从站：序列号下限</translation>
    </message>
    <message>
        <source>Identify remote slave: serial high</source>
        <translation>识别远程从站：序列号上限</translation>
    </message>
    <message>
        <source>Identify non-configured remote slave</source>
        <translation>识别未设置节点 ID 的远程从站</translation>
    </message>
    <message>
        <source>Identify slave</source>
        <translation>从站识别响应</translation>
    </message>
    <message>
        <source>Identify non-configured slave</source>
        <translation>未设置节点 ID 的从站识别响应</translation>
    </message>
    <message>
        <source>Fastscan</source>
        <translation>快速扫描（Fastscan）</translation>
    </message>
    <message>
        <source>Unknown LSS command 0x%1</source>
        <translation>未知的 LSS 命令 0x%1</translation>
    </message>
    <message>
        <source>LSS %1</source>
        <translation>LSS：%1</translation>
    </message>
    <message>
        <source>LSS %1: configuration</source>
        <translation>LSS：%1（设置状态）</translation>
    </message>
    <message>
        <source>LSS %1: waiting</source>
        <translation>LSS：%1（等待状态）</translation>
    </message>
    <message>
        <source>LSS %1: node-ID %2</source>
        <translation>LSS：%1（节点 ID %2）</translation>
    </message>
    <message>
        <source>LSS %1: error %2</source>
        <translation>LSS：%1（错误 %2）</translation>
    </message>
    <message>
        <source>LSS %1: ok</source>
        <translation>LSS：%1（成功）</translation>
    </message>
    <message>
        <source>LSS %1: %2 kbit/s</source>
        <translation>LSS：%1（波特率 %2 kbit/s）</translation>
    </message>
    <message>
        <source>LSS %1: table %2 index %3</source>
        <translation>LSS：%1（表 %2，索引 %3）</translation>
    </message>
    <message>
        <source>LSS %1: delay %2 ms</source>
        <translation>LSS：%1（延迟 %2 ms）</translation>
    </message>
    <message>
        <source>LSS %1: 0x%2</source>
        <translation>LSS：%1 = 0x%2</translation>
    </message>
    <message>
        <source>LSS Node-ID: %1</source>
        <translation>LSS：节点 ID = %1</translation>
    </message>
    <message>
        <source>LSS %1: IDNumber 0x%2, bit %3, sub %4, next %5</source>
        <translation>LSS：%1（识别号 0x%2，检查位 %3，比对项 %4，下一项 %5）</translation>
    </message>
    <message>
        <source>LSS (malformed)</source>
        <translation>LSS（格式错误）</translation>
    </message>
    <message>
        <source>LSS frame with %1 bytes; CiA 305 requires 8</source>
        <translation>LSS 帧有 %1 字节；CiA 305 规定为 8</translation>
    </message>
    <message>
        <source>EMCY node %1: %2 %3, register 0x%4, %5</source>
        <translation>EMCY 节点 %1：%2 %3，错误寄存器 0x%4，%5</translation>
    </message>
    <message>
        <source>Delta alarm number</source>
        <translation>台达报警号</translation>
    </message>
    <message>
        <source>AIMOTOR fault code</source>
        <translation>AIMOTOR 故障码</translation>
    </message>
    <message>
        <source>M1 alarm code</source>
        <translation>M1 报警码</translation>
    </message>
    <message>
        <source>M2 alarm code</source>
        <translation>M2 报警码</translation>
    </message>
    <message>
        <source>%1; %2</source>
        <translation>%1；%2</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1、%2</translation>
    </message>
    <message>
        <source>%1: the bus is listen-only: CoScope sends nothing, so no heartbeat and no guard</source>
        <translation>%1：总线为只听：CoScope 不发送任何帧，因此没有心跳也没有保护</translation>
    </message>
    <message>
        <source>%1: CoScope&apos;s heartbeat node-ID %2 is the drive&apos;s own; choose another in the master settings</source>
        <translation>%1：CoScope 的心跳节点 ID %2 与驱动器相同；请在主站设置中另选</translation>
    </message>
    <message>
        <source>%1: CoScope&apos;s heartbeat cannot start: %2</source>
        <translation>%1：CoScope 的心跳无法启动：%2</translation>
    </message>
    <message>
        <source>%1 may still be enabled: it keeps watching CoScope&apos;s heartbeat (1016h, 6007h not put back), so it stops by itself when the heartbeat stops</source>
        <translation>%1 可能仍为使能：它继续监视 CoScope 的心跳（1016h、6007h 未写回），心跳停止时会自行停止</translation>
    </message>
    <message>
        <source>%1: the old 1016h/6007h could not be put back (the bus is closed); check them</source>
        <translation>%1：原来的 1016h/6007h 无法写回（总线已关闭）；请检查</translation>
    </message>
    <message>
        <source>%1: heartbeat consumer 1016h and 6007h put back before the bus closed</source>
        <translation>%1：总线关闭前已写回消费者心跳时间 1016h 与 6007h</translation>
    </message>
    <message>
        <source>%1: the old 1016h/6007h were not all put back (%2); check them</source>
        <translation>%1：原来的 1016h/6007h 未全部写回（%2）；请检查</translation>
    </message>
    <message>
        <source>%1 watches CoScope&apos;s heartbeat (node %2) in 1016h:%3 with %4 ms; when it stops: %5</source>
        <translation>%1 以 1016h:%3 监视 CoScope 的心跳（节点 %2），%4 ms；心跳停止时：%5</translation>
    </message>
    <message>
        <source>%1: heartbeat consumer 1016h:%2 = %3%4 put back</source>
        <translation>%1：已写回消费者心跳时间 1016h:%2 = %3%4</translation>
    </message>
    <message>
        <source>node %1: node guarding answer with toggle bit %2, %3 expected</source>
        <translation>节点 %1：节点保护应答的翻转位为 %2，应为 %3</translation>
    </message>
    <message>
        <source>node %1: no answer to a node guarding request within the guard time %2 ms</source>
        <translation>节点 %1：节点保护请求在节点守护时间 %2 ms 内无应答</translation>
    </message>
    <message>
        <source>set-point acknowledge</source>
        <translation>设定点确认</translation>
    </message>
    <message>
        <source>following error</source>
        <translation>位置跟随超差</translation>
    </message>
    <message>
        <source>zero speed</source>
        <translation>零速</translation>
    </message>
    <message>
        <source>max slippage error</source>
        <translation>最大滑差错误</translation>
    </message>
    <message>
        <source>homing attained</source>
        <translation>回原点完成</translation>
    </message>
    <message>
        <source>homing error</source>
        <translation>回原点错误</translation>
    </message>
    <message>
        <source>ip mode active</source>
        <translation>IP 模式激活</translation>
    </message>
    <message>
        <source>drive follows the command value</source>
        <translation>驱动器跟随指令值</translation>
    </message>
    <message>
        <source>FFh (event)</source>
        <translation>FFh（事件触发）</translation>
    </message>
    <message>
        <source>FEh (event, manufacturer)</source>
        <translation>FEh（事件触发，制造商定义）</translation>
    </message>
    <message>
        <source>Current position is home (no movement)</source>
        <translation>当前位置即为原点（不移动）</translation>
    </message>
    <message>
        <source>Current position is home (no movement; the default)</source>
        <translation>当前位置即为原点（不移动；默认）</translation>
    </message>
    <message>
        <source>Home switch searched in the negative direction (stops on its edge)</source>
        <translation>负向搜索原点开关（停在其边沿）</translation>
    </message>
    <message>
        <source>Home switch searched in the negative direction, then the Z pulse</source>
        <translation>负向搜索原点开关，再找 Z 相信号</translation>
    </message>
    <message>
        <source>Home switch searched in the positive direction (stops on its edge)</source>
        <translation>正向搜索原点开关（停在其边沿）</translation>
    </message>
    <message>
        <source>Home switch searched in the positive direction, then the Z pulse</source>
        <translation>正向搜索原点开关，再找 Z 相信号</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), lower edge: Z pulse above the edge</source>
        <translation>原点开关，负向起始（负向限位开关换向），下边沿：边沿上方的 Z 相信号</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), lower edge: Z pulse below the edge</source>
        <translation>原点开关，负向起始（负向限位开关换向），下边沿：边沿下方的 Z 相信号</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), lower edge: index pulse above the edge</source>
        <translation>原点开关，负向起始（负向限位开关换向），下边沿：边沿上方的索引脉冲</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), lower edge: index pulse below the edge</source>
        <translation>原点开关，负向起始（负向限位开关换向），下边沿：边沿下方的索引脉冲</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), lower edge: its edge, reached from above</source>
        <translation>原点开关，负向起始（负向限位开关换向），下边沿：其边沿，从上方到达</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), lower edge: its edge, reached from above (the same as 29, Delta manual §4.6)</source>
        <translation>原点开关，负向起始（负向限位开关换向），下边沿：其边沿，从上方到达（与 29 相同，台达手册 §4.6）</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), lower edge: its edge, reached from below</source>
        <translation>原点开关，负向起始（负向限位开关换向），下边沿：其边沿，从下方到达</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), upper edge: Z pulse above the edge</source>
        <translation>原点开关，负向起始（负向限位开关换向），上边沿：边沿上方的 Z 相信号</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), upper edge: Z pulse below the edge</source>
        <translation>原点开关，负向起始（负向限位开关换向），上边沿：边沿下方的 Z 相信号</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), upper edge: index pulse above the edge</source>
        <translation>原点开关，负向起始（负向限位开关换向），上边沿：边沿上方的索引脉冲</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), upper edge: index pulse below the edge</source>
        <translation>原点开关，负向起始（负向限位开关换向），上边沿：边沿下方的索引脉冲</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), upper edge: its edge, reached from above</source>
        <translation>原点开关，负向起始（负向限位开关换向），上边沿：其边沿，从上方到达</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), upper edge: its edge, reached from above (the same as 27, Delta manual §4.6)</source>
        <translation>原点开关，负向起始（负向限位开关换向），上边沿：其边沿，从上方到达（与 27 相同，台达手册 §4.6）</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), upper edge: its edge, reached from below</source>
        <translation>原点开关，负向起始（负向限位开关换向），上边沿：其边沿，从下方到达</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), lower edge: Z pulse above the edge</source>
        <translation>原点开关，正向起始（正向限位开关换向），下边沿：边沿上方的 Z 相信号</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), lower edge: Z pulse below the edge</source>
        <translation>原点开关，正向起始（正向限位开关换向），下边沿：边沿下方的 Z 相信号</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), lower edge: index pulse above the edge</source>
        <translation>原点开关，正向起始（正向限位开关换向），下边沿：边沿上方的索引脉冲</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), lower edge: index pulse below the edge</source>
        <translation>原点开关，正向起始（正向限位开关换向），下边沿：边沿下方的索引脉冲</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), lower edge: its edge, reached from above</source>
        <translation>原点开关，正向起始（正向限位开关换向），下边沿：其边沿，从上方到达</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), lower edge: its edge, reached from below</source>
        <translation>原点开关，正向起始（正向限位开关换向），下边沿：其边沿，从下方到达</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), lower edge: its edge, reached from below (the same as 23, Delta manual §4.6)</source>
        <translation>原点开关，正向起始（正向限位开关换向），下边沿：其边沿，从下方到达（与 23 相同，台达手册 §4.6）</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), upper edge: Z pulse above the edge</source>
        <translation>原点开关，正向起始（正向限位开关换向），上边沿：边沿上方的 Z 相信号</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), upper edge: Z pulse below the edge</source>
        <translation>原点开关，正向起始（正向限位开关换向），上边沿：边沿下方的 Z 相信号</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), upper edge: index pulse above the edge</source>
        <translation>原点开关，正向起始（正向限位开关换向），上边沿：边沿上方的索引脉冲</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), upper edge: index pulse below the edge</source>
        <translation>原点开关，正向起始（正向限位开关换向），上边沿：边沿下方的索引脉冲</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), upper edge: its edge, reached from above</source>
        <translation>原点开关，正向起始（正向限位开关换向），上边沿：其边沿，从上方到达</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), upper edge: its edge, reached from below</source>
        <translation>原点开关，正向起始（正向限位开关换向），上边沿：其边沿，从下方到达</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), upper edge: its edge, reached from below (the same as 25, Delta manual §4.6)</source>
        <translation>原点开关，正向起始（正向限位开关换向），上边沿：其边沿，从下方到达（与 25 相同，台达手册 §4.6）</translation>
    </message>
    <message>
        <source>Mechanical end stop in the negative direction, at low speed with the homing torque limit H05-58</source>
        <translation>负向低速搜索机械极限位，转矩限制为回原点转矩限制 H05-58</translation>
    </message>
    <message>
        <source>Mechanical end stop in the positive direction, at low speed with the homing torque limit H05-58</source>
        <translation>正向低速搜索机械极限位，转矩限制为回原点转矩限制 H05-58</translation>
    </message>
    <message>
        <source>Negative home switch: Z pulse above the edge</source>
        <translation>负向原点开关：边沿上方的 Z 相信号</translation>
    </message>
    <message>
        <source>Negative home switch: Z pulse below the edge</source>
        <translation>负向原点开关：边沿下方的 Z 相信号</translation>
    </message>
    <message>
        <source>Negative home switch: index pulse above the edge</source>
        <translation>负向原点开关：边沿上方的索引脉冲</translation>
    </message>
    <message>
        <source>Negative home switch: index pulse below the edge</source>
        <translation>负向原点开关：边沿下方的索引脉冲</translation>
    </message>
    <message>
        <source>Negative home switch: its edge, reached from above</source>
        <translation>负向原点开关：其边沿，从上方到达</translation>
    </message>
    <message>
        <source>Negative home switch: its edge, reached from above (the same as 21, Delta manual §4.6)</source>
        <translation>负向原点开关：其边沿，从上方到达（与 21 相同，台达手册 §4.6）</translation>
    </message>
    <message>
        <source>Negative home switch: its edge, reached from below</source>
        <translation>负向原点开关：其边沿，从下方到达</translation>
    </message>
    <message>
        <source>Negative limit switch, then back to the first Z pulse</source>
        <translation>负向限位开关，再回到第一个 Z 相信号</translation>
    </message>
    <message>
        <source>Negative limit switch, then back to the first index pulse</source>
        <translation>负向限位开关，再回到第一个索引脉冲</translation>
    </message>
    <message>
        <source>Negative limit switch: its edge, backing off the switch</source>
        <translation>负向限位开关：脱离开关时的边沿</translation>
    </message>
    <message>
        <source>Negative overtravel switch (stops on its edge)</source>
        <translation>反向超程开关（停在其边沿）</translation>
    </message>
    <message>
        <source>Negative overtravel switch, then the Z pulse</source>
        <translation>反向超程开关，再找 Z 相信号</translation>
    </message>
    <message>
        <source>Next Z pulse in the negative direction</source>
        <translation>负向的下一个 Z 相信号</translation>
    </message>
    <message>
        <source>Next Z pulse in the positive direction</source>
        <translation>正向的下一个 Z 相信号</translation>
    </message>
    <message>
        <source>Next index pulse in the negative direction</source>
        <translation>负向的下一个索引脉冲</translation>
    </message>
    <message>
        <source>Next index pulse in the positive direction</source>
        <translation>正向的下一个索引脉冲</translation>
    </message>
    <message>
        <source>Positive home switch: Z pulse above the edge</source>
        <translation>正向原点开关：边沿上方的 Z 相信号</translation>
    </message>
    <message>
        <source>Positive home switch: Z pulse below the edge</source>
        <translation>正向原点开关：边沿下方的 Z 相信号</translation>
    </message>
    <message>
        <source>Positive home switch: index pulse above the edge</source>
        <translation>正向原点开关：边沿上方的索引脉冲</translation>
    </message>
    <message>
        <source>Positive home switch: index pulse below the edge</source>
        <translation>正向原点开关：边沿下方的索引脉冲</translation>
    </message>
    <message>
        <source>Positive home switch: its edge, reached from above</source>
        <translation>正向原点开关：其边沿，从上方到达</translation>
    </message>
    <message>
        <source>Positive home switch: its edge, reached from below</source>
        <translation>正向原点开关：其边沿，从下方到达</translation>
    </message>
    <message>
        <source>Positive home switch: its edge, reached from below (the same as 19, Delta manual §4.6)</source>
        <translation>正向原点开关：其边沿，从下方到达（与 19 相同，台达手册 §4.6）</translation>
    </message>
    <message>
        <source>Positive limit switch, then back to the first Z pulse</source>
        <translation>正向限位开关，再回到第一个 Z 相信号</translation>
    </message>
    <message>
        <source>Positive limit switch, then back to the first index pulse</source>
        <translation>正向限位开关，再回到第一个索引脉冲</translation>
    </message>
    <message>
        <source>Positive limit switch: its edge, backing off the switch</source>
        <translation>正向限位开关：脱离开关时的边沿</translation>
    </message>
    <message>
        <source>Positive overtravel switch (stops on its edge)</source>
        <translation>正向超程开关（停在其边沿）</translation>
    </message>
    <message>
        <source>Positive overtravel switch, then the Z pulse</source>
        <translation>正向超程开关，再找 Z 相信号</translation>
    </message>
    <message>
        <source>Z pulse searched in the negative direction</source>
        <translation>负向搜索 Z 相信号</translation>
    </message>
    <message>
        <source>Z pulse searched in the positive direction</source>
        <translation>正向搜索 Z 相信号</translation>
    </message>
    <message>
        <source>No reason given</source>
        <translation>未说明原因</translation>
    </message>
</context>
<context>
    <name>Ds402Fault</name>
    <message>
        <source>Error code (603Fh) %1h</source>
        <extracomment>CiA 402 wizard, a drive fault: %1 = the error code in hex</extracomment>
        <translation>错误码（603Fh）%1h</translation>
    </message>
    <message>
        <source> — vendor alarm %1</source>
        <extracomment>CiA 402 wizard, after the error code: %1 = the vendor&apos;s alarm code and name (&quot;AL013 Emergency stop&quot;)</extracomment>
        <translation>——厂商报警 %1</translation>
    </message>
    <message>
        <source>alarm number 0x%1 (not in the %2 table)</source>
        <extracomment>%1 = the vendor alarm number in hex, %2 = the alarm table&apos;s name (e.g. delta-asda-a2)</extracomment>
        <translation>报警编号 0x%1（不在 %2 报警表中）</translation>
    </message>
</context>
<context>
    <name>Ds402StateDiagram</name>
    <message>
        <source>13 any fault</source>
        <translation>13 任何故障</translation>
    </message>
</context>
<context>
    <name>Ds402VendorNotes</name>
    <message>
        <source>P1-01 must be 0x0C (standard CANopen mode) or the drive ignores the controlword. Do not send NMT Reset Node while the servo is on: the drive raises AL401.</source>
        <translation>P1-01 必须为 0x0C（标准 CANopen 模式），否则驱动器会忽略控制字。伺服启动（Servo On）时请勿发送 NMT Reset Node：驱动器会发出 AL401。</translation>
    </message>
    <message>
        <source>H02-00 must be 8 (CANopen control) or the drive ignores the controlword.</source>
        <translation>H02-00 必须为 8（CANopen 控制），否则驱动器会忽略控制字。</translation>
    </message>
    <message>
        <source>The DEXMART DEV has no CiA 402 state machine: its two motors are run through the Multi-Drive objects (3051h/3052h). Use the Object dictionary dock for it.</source>
        <translation>DEXMART DEV 没有 CiA 402 状态机：它的两台电机是通过 Multi-Drive 对象（3051h/3052h）控制。请改用对象字典面板。</translation>
    </message>
</context>
<context>
    <name>EnabledDrivesQuestion</name>
    <message>
        <source>Node %1 is enabled by CoScope: disable it and quit?</source>
        <translation>节点 %1 由 CoScope 使能中：要将其停用并退出吗？</translation>
    </message>
    <message>
        <source>Nodes %1 are enabled by CoScope: disable them and quit?</source>
        <translation>节点 %1 由 CoScope 使能中：要将其停用并退出吗？</translation>
    </message>
    <message>
        <source>Node %1 is enabled by CoScope: disable it and disconnect?</source>
        <translation>节点 %1 由 CoScope 使能中：要将其停用并断开连接吗？</translation>
    </message>
    <message>
        <source>Nodes %1 are enabled by CoScope: disable them and disconnect?</source>
        <translation>节点 %1 由 CoScope 使能中：要将其停用并断开连接吗？</translation>
    </message>
    <message>
        <source>Node %1 is enabled by CoScope: disable it and connect anew?</source>
        <translation>节点 %1 由 CoScope 使能中：要将其停用并重新连接吗？</translation>
    </message>
    <message>
        <source>Nodes %1 are enabled by CoScope: disable them and connect anew?</source>
        <translation>节点 %1 由 CoScope 使能中：要将其停用并重新连接吗？</translation>
    </message>
    <message>
        <source>Node %1 is enabled by CoScope: disable it and open the log?</source>
        <translation>节点 %1 由 CoScope 使能中：要将其停用并打开日志吗？</translation>
    </message>
    <message>
        <source>Nodes %1 are enabled by CoScope: disable them and open the log?</source>
        <translation>节点 %1 由 CoScope 使能中：要将其停用并打开日志吗？</translation>
    </message>
    <message>
        <source>%1 (axis %2)</source>
        <translation>%1（轴 %2）</translation>
    </message>
    <message>
        <source>Drive enabled</source>
        <translation>驱动器使能中</translation>
    </message>
    <message>
        <source>CoScope sends Disable voltage (6040h = 0000h; Quick stop first to a drive that may be moving) and waits to see it on the bus before the connection closes. Cancel leaves everything as it is.</source>
        <translation>CoScope 会发送断开电压（Disable voltage，6040h = 0000h；可能在运动的驱动器先发送快速停止），并在连接关闭前等待在总线上看到该帧。取消则一切保持原样。</translation>
    </message>
    <message>
        <source>Disable and quit</source>
        <translation>停用并退出</translation>
    </message>
    <message>
        <source>Disable and disconnect</source>
        <translation>停用并断开连接</translation>
    </message>
    <message>
        <source>Disable and connect</source>
        <translation>停用并连接</translation>
    </message>
    <message>
        <source>Disable and open the log</source>
        <translation>停用并打开日志</translation>
    </message>
</context>
<context>
    <name>EventLog</name>
    <message>
        <source>EMCY reset</source>
        <translation>EMCY 复位</translation>
    </message>
    <message>
        <source>SDO abort</source>
        <translation>SDO 中止</translation>
    </message>
    <message>
        <source>NMT state</source>
        <translation>NMT 状态</translation>
    </message>
    <message>
        <source>Boot-up</source>
        <translation>启动（Boot-up）</translation>
    </message>
    <message>
        <source>NMT command</source>
        <translation>NMT 命令</translation>
    </message>
    <message>
        <source>Heartbeat timeout</source>
        <translation>心跳超时</translation>
    </message>
    <message>
        <source>Bus error</source>
        <translation>总线错误</translation>
    </message>
    <message>
        <source>Dropped frames</source>
        <translation>丢失的帧</translation>
    </message>
    <message>
        <source>Info</source>
        <translation>信息</translation>
    </message>
    <message>
        <source>all nodes</source>
        <translation>所有节点</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>Heartbeat back after timeout</source>
        <translation>超时后心跳恢复</translation>
    </message>
    <message>
        <source>State %1</source>
        <translation>状态 %1</translation>
    </message>
    <message>
        <source>No heartbeat for %1 ms (period %2 ms)</source>
        <translation>%1 ms 内没有心跳（周期 %2 ms）</translation>
    </message>
    <message>
        <source>error</source>
        <translation>错误</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>info</source>
        <translation>信息</translation>
    </message>
</context>
<context>
    <name>FrameDecoder</name>
    <message>
        <source>NMT (short frame)</source>
        <translation>NMT（短帧）</translation>
    </message>
    <message>
        <source>NMT frame must carry 2 bytes</source>
        <translation>NMT 帧必须有 2 个字节</translation>
    </message>
    <message>
        <source>all nodes</source>
        <translation>所有节点</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>NMT node control</source>
        <translation>NMT 节点控制</translation>
    </message>
    <message>
        <source>Command specifier</source>
        <translation>命令标识符</translation>
    </message>
    <message>
        <source>Node-ID</source>
        <translation>节点 ID</translation>
    </message>
    <message>
        <source>0 (all)</source>
        <translation>0（全部）</translation>
    </message>
    <message>
        <source>Node guarding request to node %1</source>
        <translation>对节点 %1 的节点保护请求</translation>
    </message>
    <message>
        <source>Node guarding request (RTR)</source>
        <translation>节点保护请求（RTR）</translation>
    </message>
    <message>
        <source>NMT error control (empty)</source>
        <translation>NMT 错误控制（空）</translation>
    </message>
    <message>
        <source>error control frame without state byte</source>
        <translation>错误控制帧缺少状态字节</translation>
    </message>
    <message>
        <source>Boot-up node %1</source>
        <translation>节点 %1 启动（Boot-up）</translation>
    </message>
    <message>
        <source>Heartbeat node %1: %2</source>
        <translation>节点 %1 心跳：%2</translation>
    </message>
    <message>
        <source>Boot-up</source>
        <translation>启动（Boot-up）</translation>
    </message>
    <message>
        <source>Heartbeat / guarding</source>
        <translation>心跳／节点保护</translation>
    </message>
    <message>
        <source>Toggle</source>
        <translation>翻转位</translation>
    </message>
    <message>
        <source>NMT state</source>
        <translation>NMT 状态</translation>
    </message>
    <message>
        <source>EMCY node %1: error reset</source>
        <translation>EMCY 节点 %1：错误复位</translation>
    </message>
    <message>
        <source>EMCY node %1: %2 %3, reg %4</source>
        <translation>EMCY 节点 %1：%2 %3，寄存器 %4</translation>
    </message>
    <message>
        <source>EMCY frame shorter than 8 bytes</source>
        <translation>EMCY 帧短于 8 字节</translation>
    </message>
    <message>
        <source>Emergency</source>
        <translation>紧急报文</translation>
    </message>
    <message>
        <source>Error code</source>
        <translation>错误码</translation>
    </message>
    <message>
        <source>Error register (1001h)</source>
        <translation>错误寄存器（1001h）</translation>
    </message>
    <message>
        <source>Bit %1</source>
        <translation>位 %1</translation>
    </message>
    <message>
        <source>Manufacturer-specific</source>
        <translation>制造商定义</translation>
    </message>
    <message>
        <source>SDO %1 node %2 %3</source>
        <translation>SDO %1 节点 %2 %3</translation>
    </message>
    <message>
        <source>, %1 bytes</source>
        <translation>，%1 字节</translation>
    </message>
    <message>
        <source>SDO request (client → server)</source>
        <translation>SDO 请求（客户端 → 服务器）</translation>
    </message>
    <message>
        <source>SDO response (server → client)</source>
        <translation>SDO 响应（服务器 → 客户端）</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>命令</translation>
    </message>
    <message>
        <source>Index</source>
        <translation>索引</translation>
    </message>
    <message>
        <source>Sub-index</source>
        <translation>子索引</translation>
    </message>
    <message>
        <source>Abort code</source>
        <translation>中止码</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>数据</translation>
    </message>
    <message>
        <source>Segment data</source>
        <translation>分段数据</translation>
    </message>
    <message>
        <source>Error frame, class %1</source>
        <translation>错误帧，类别 %1</translation>
    </message>
    <message>
        <source>Error frame</source>
        <translation>错误帧</translation>
    </message>
    <message>
        <source>SYNC counter %1</source>
        <translation>SYNC 计数器 %1</translation>
    </message>
    <message>
        <source>TIME stamp</source>
        <translation>时间戳（TIME）</translation>
    </message>
    <message>
        <source>(empty)</source>
        <translation>（空）</translation>
    </message>
    <message>
        <source>LSS command</source>
        <translation>LSS 命令</translation>
    </message>
    <message>
        <source>(29-bit identifier, not CANopen)</source>
        <translation>（29 位标识符，非 CANopen）</translation>
    </message>
    <message>
        <source>%1 node %2, %3 bytes</source>
        <translation>%1 节点 %2，%3 字节</translation>
    </message>
</context>
<context>
    <name>GapSaveQuestion</name>
    <message>
        <source>Save trace</source>
        <translation>保存跟踪</translation>
    </message>
    <message numerus="yes">
        <source>The trace has %n gap(s) (adapter lost); the %1 format cannot hold them, so the saved file will not show where frames are missing. pcapng, ASC, TRC and CSV keep them.</source>
        <translation>
            <numerusform>跟踪中有 %n 处中断（适配器丢失）；%1 格式无法保存中断，保存后将看不出哪里缺少帧。pcapng、ASC、TRC 和 CSV 会保留中断。</numerusform>
        </translation>
    </message>
    <message>
        <source>Save anyway</source>
        <translation>仍要保存</translation>
    </message>
</context>
<context>
    <name>HealthRules</name>
    <message>
        <source>Node %1 booted up %2 time(s) without an NMT reset command before it.</source>
        <translation>节点 %1 在没有 NMT 复位命令的情况下启动了 %2 次。</translation>
    </message>
    <message>
        <source>A device that restarts on its own loses its state: a drive drops its enable and the machine stops.</source>
        <translation>设备自行重启会丢失原有状态：驱动器失去使能，机器随之停止。</translation>
    </message>
    <message>
        <source>Check the node&apos;s supply voltage and wiring, its watchdog and error history, and the frames just before each boot-up.</source>
        <translation>请检查该节点的电源电压与接线、看门狗与错误记录，以及每次启动前的帧。</translation>
    </message>
    <message>
        <source>Node %1&apos;s %2 stopped: nothing for %3 at the end of the log (period %4).</source>
        <translation>节点 %1 的%2已停止：记录末尾有 %3 没有任何报文（周期 %4）。</translation>
    </message>
    <message>
        <source>The master&apos;s heartbeat consumer sees the node as lost and the application stops using it.</source>
        <translation>主站的心跳消费者会判定该节点丢失，应用程序便停止使用它。</translation>
    </message>
    <message>
        <source>Check that node %1 still has power and is on the bus (cable, connector, termination), and whether its 1017h was set to 0.</source>
        <translation>请确认节点 %1 仍有电源且连在总线上（电缆、接头、终端电阻），并检查其 1017h 是否被设为 0。</translation>
    </message>
    <message>
        <source>Node %1&apos;s %2 was missing %3 time(s) after regular beats (longest gap %4, period %5).</source>
        <translation>节点 %1 的%2在规律发送后中断了 %3 次（最长间隔 %4，周期 %5）。</translation>
    </message>
    <message>
        <source>A consumer whose heartbeat time (1016h) is shorter than the gap raises a heartbeat error and may stop the machine.</source>
        <translation>消费者心跳时间（1016h）短于此间隔时，会产生心跳错误并可能使机器停止。</translation>
    </message>
    <message>
        <source>Look at the frames around each gap: error frames, bus load, a reset of node %1, a loose connection.</source>
        <translation>请查看每个间隔前后的帧：错误帧、总线负载、节点 %1 是否复位、接线是否松动。</translation>
    </message>
    <message>
        <source>Node %1&apos;s %2 came late %3 time(s) (over 1.5 times the %4 period).</source>
        <translation>节点 %1 的%2延迟了 %3 次（超过周期 %4 的 1.5 倍）。</translation>
    </message>
    <message>
        <source>Late beats eat the consumer&apos;s margin: a little more delay becomes a heartbeat error.</source>
        <translation>延迟的心跳会耗尽消费者的裕量：再多一点延迟就会变成心跳错误。</translation>
    </message>
    <message>
        <source>Compare with the bus load at those times, and check that the consumer time (1016h) leaves margin over %4.</source>
        <translation>请对照当时的总线负载，并确认消费者时间（1016h）比 %4 留有裕量。</translation>
    </message>
    <message>
        <source>Node %1 reported EMCY %2 (%3) %4 time(s).</source>
        <translation>节点 %1 报告了 EMCY %2（%3）共 %4 次。</translation>
    </message>
    <message>
        <source>The device signals a fault; a drive in Fault stops its motor until the fault is reset.</source>
        <translation>设备发出故障信号；驱动器处于故障状态时会停止电机，直到故障复位。</translation>
    </message>
    <message>
        <source>Look up %2 in the device&apos;s alarm list, remove the cause, then reset the fault (controlword bit 7).</source>
        <translation>请在设备的故障码表中查询 %2，排除原因后再复位故障（控制字 bit 7）。</translation>
    </message>
    <message>
        <source>Node %1 left %2 SDO request(s) unanswered (no response within 1 s).</source>
        <translation>节点 %1 有 %2 个 SDO 请求未响应（1 秒内没有回复）。</translation>
    </message>
    <message>
        <source>The master&apos;s parameter access fails: a configuration step may have been skipped.</source>
        <translation>主站的参数访问失败：可能有配置步骤被跳过。</translation>
    </message>
    <message>
        <source>Check node %1&apos;s node-ID, power and NMT state (a stopped node serves no SDO), and the bus load at those times.</source>
        <translation>请检查节点 %1 的节点 ID、电源与 NMT 状态（停止状态的节点不处理 SDO），以及当时的总线负载。</translation>
    </message>
    <message>
        <source>Node %1 aborted %4 SDO transfer(s) with %2 (%3).</source>
        <translation>节点 %1 以 %2（%3）中止了 %4 次 SDO 传输。</translation>
    </message>
    <message>
        <source>The value was not read or written: a configuration that relies on it is incomplete.</source>
        <translation>该值没有被读取或写入：依赖它的配置并不完整。</translation>
    </message>
    <message>
        <source>Look at the object of each frame: does node %1 have it (its EDS), is it writable, is the value in range?</source>
        <translation>请查看每个帧的对象：节点 %1 是否有此对象（见其 EDS）、是否可写、数值是否在范围内？</translation>
    </message>
    <message>
        <source>Node %1 answered SDO requests slowly: %2 at the 99th percentile, the slowest %3.</source>
        <translation>节点 %1 响应 SDO 请求很慢：第 99 百分位数为 %2，最慢 %3。</translation>
    </message>
    <message>
        <source>A master with a short SDO timeout aborts such transfers, and start-up configuration takes longer.</source>
        <translation>SDO 超时设置较短的主站会中止这类传输，启动时的配置也会更久。</translation>
    </message>
    <message>
        <source>Check what node %1 does meanwhile (storing parameters, 1010h) and the bus load; raise the master&apos;s SDO timeout if needed.</source>
        <translation>请检查节点 %1 当时在做什么（保存参数，1010h）以及总线负载；必要时加长主站的 SDO 超时。</translation>
    </message>
    <message>
        <source>%1 CAN error frame(s) were recorded.</source>
        <translation>记录到 %1 个 CAN 错误帧。</translation>
    </message>
    <message>
        <source>Error frames destroy frames and delay others; many of them take nodes to error passive or bus-off.</source>
        <translation>错误帧会破坏帧并延迟其他帧；数量一多，节点就会进入错误被动或总线关闭状态。</translation>
    </message>
    <message>
        <source>Check the termination (120 ohm at both ends), cable, shield and ground, and that every node uses the same bit rate.</source>
        <translation>请检查终端电阻（两端各 120 欧姆）、电缆、屏蔽与接地，并确认所有节点使用相同的波特率。</translation>
    </message>
    <message>
        <source>%1 SYNC cycle(s) were missing (period %2).</source>
        <translation>缺少了 %1 个 SYNC 周期（周期 %2）。</translation>
    </message>
    <message>
        <source>Synchronous PDOs are not sent or applied in those cycles; axes in a cyclic synchronous mode miss set-points.</source>
        <translation>这些周期内同步 PDO 不会发送或生效；处于周期同步模式的轴会丢失设定值。</translation>
    </message>
    <message>
        <source>Check the SYNC producer&apos;s timing and load, and the bus load at those times.</source>
        <translation>请检查 SYNC 生产者的时序与负载，以及当时的总线负载。</translation>
    </message>
    <message>
        <source>The bus load peaks at %1 % (average %2 %) at %3 bit/s.</source>
        <translation>总线负载峰值为 %1 %（平均 %2 %），波特率 %3 bit/s。</translation>
    </message>
    <message>
        <source>Above about 70 % the low-priority frames (SDO, heartbeat) wait and may time out.</source>
        <translation>负载超过约 70 % 时，低优先级的帧（SDO、心跳）会等待并可能超时。</translation>
    </message>
    <message>
        <source>Lower PDO rates or mapped data, use inhibit times or event timers, or raise the bit rate.</source>
        <translation>请降低 PDO 频率或映射的数据量、使用禁止时间或事件定时器，或提高波特率。</translation>
    </message>
    <message>
        <source>%1 (%2) is sent to node %3, which never sent anything.</source>
        <translation>%1（%2）发往节点 %3，但该节点从未发送任何报文。</translation>
    </message>
    <message>
        <source>The data goes nowhere: node %3 is missing or has another node-ID.</source>
        <translation>数据没有接收者：节点 %3 不存在或使用了其他节点 ID。</translation>
    </message>
    <message>
        <source>Check that node %3 is powered and on the bus, and its node-ID.</source>
        <translation>请确认节点 %3 有电源且连在总线上，并检查其节点 ID。</translation>
    </message>
    <message>
        <source>%1 of node %2 (%3) comes every %4 with a jitter of %5.</source>
        <translation>节点 %2 的 %1（%3）每 %4 一次，抖动为 %5。</translation>
    </message>
    <message>
        <source>Cyclic data that arrives unevenly makes control and plots uneven.</source>
        <translation>周期数据到达不均匀，会使控制与曲线也不均匀。</translation>
    </message>
    <message>
        <source>Check the producer&apos;s timing (SYNC or event timer) and the bus load; the frames listed end the most irregular intervals.</source>
        <translation>请检查生产者的时序（SYNC 或事件定时器）与总线负载；列出的帧是最不规律间隔的结尾。</translation>
    </message>
    <message>
        <source>RPDO%1 of node %2 (%3) is valid but nobody sends it.</source>
        <translation>节点 %2 的 RPDO%1（%3）已启用，但没有人发送它。</translation>
    </message>
    <message>
        <source>Node %2 waits for data that never comes; with an RPDO timeout it may fault.</source>
        <translation>节点 %2 在等待永远不会来的数据；若设有 RPDO 超时，可能会进入故障。</translation>
    </message>
    <message>
        <source>Map and enable the matching TPDO on the producer, or make this RPDO invalid (COB-ID bit 31).</source>
        <translation>请在生产者上映射并启用对应的 TPDO，或将此 RPDO 设为无效（COB-ID bit 31）。</translation>
    </message>
    <message>
        <source>%1 node-ID(s) (%2..%3) got an SDO request from a master and never answered.</source>
        <translation>有 %1 个节点 ID（%2..%3）收到主站的 SDO 请求但从未响应。</translation>
    </message>
    <message>
        <source>A device the master expects may be missing, or the master scanned the network.</source>
        <translation>主站预期的设备可能不存在，或主站正在扫描网络。</translation>
    </message>
    <message>
        <source>Compare with the devices the machine should have, and their node-IDs.</source>
        <translation>请对照机器应有的设备及其节点 ID。</translation>
    </message>
    <message>
        <source>%1 frame(s) are not CANopen.</source>
        <translation>有 %1 个帧不是 CANopen。</translation>
    </message>
    <message>
        <source>They come from another protocol on the same bus (such as J1939) or from a device set up wrongly.</source>
        <translation>它们来自同一总线上的其他协议（例如 J1939），或来自配置错误的设备。</translation>
    </message>
    <message>
        <source>Look at their identifiers in the trace.</source>
        <translation>请在跟踪中查看它们的标识符。</translation>
    </message>
    <message>
        <source>CoScope&apos;s scan (frames sent by the recording side) asked %1 node-ID(s) (%2..%3) that did not answer.</source>
        <translation>CoScope 的扫描（记录端发送的帧）询问了 %1 个没有响应的节点 ID（%2..%3）。</translation>
    </message>
    <message>
        <source>This is how a scan finds devices: no device is at fault.</source>
        <translation>扫描就是这样找出设备的：没有任何设备有问题。</translation>
    </message>
    <message>
        <source>Nothing to fix: these requests are CoScope&apos;s own.</source>
        <translation>无需处理：这些请求是 CoScope 自己发送的。</translation>
    </message>
    <message>
        <source>Node %1 aborted %4 SDO request(s) that CoScope sent, with %2 (%3).</source>
        <translation>节点 %1 以 %2（%3）中止了 CoScope 发送的 %4 个 SDO 请求。</translation>
    </message>
    <message>
        <source>CoScope&apos;s own requests (a scan reading optional objects, a read or write of the user) caused them: not a device fault.</source>
        <translation>这是 CoScope 自己的请求（扫描读取可选对象、用户的读写）所造成：不是设备故障。</translation>
    </message>
    <message>
        <source>Nothing to fix unless you expected node %1 to have that object.</source>
        <translation>除非您预期节点 %1 应有该对象，否则无需处理。</translation>
    </message>
    <message>
        <source>Node %1 did not answer %2 SDO request(s) that CoScope sent.</source>
        <translation>节点 %1 没有响应 CoScope 发送的 %2 个 SDO 请求。</translation>
    </message>
    <message>
        <source>CoScope&apos;s own requests went unanswered (a scan probing, or the node was busy): not counted as a device fault.</source>
        <translation>CoScope 自己的请求没有得到响应（扫描探测，或节点忙碌）：不算设备故障。</translation>
    </message>
    <message>
        <source>Nothing to fix unless node %1 should have answered.</source>
        <translation>除非节点 %1 应该响应，否则无需处理。</translation>
    </message>
    <message>
        <source>heartbeat</source>
        <translation>心跳</translation>
    </message>
    <message>
        <source>guarding</source>
        <translation>节点保护</translation>
    </message>
</context>
<context>
    <name>HelpMenu</name>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>CoScope &amp;guide</source>
        <translation>CoScope 使用指南(&amp;G)</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>键盘快捷键(&amp;K)</translation>
    </message>
    <message>
        <source>&amp;About CoScope</source>
        <translation>关于 CoScope(&amp;A)</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>关于 Qt(&amp;Q)</translation>
    </message>
</context>
<context>
    <name>LogLoadJob</name>
    <message>
        <source>Opening %1</source>
        <translation>正在打开 %1</translation>
    </message>
    <message>
        <source>%1: cannot open</source>
        <translation>%1：无法打开</translation>
    </message>
</context>
<context>
    <name>LogSaveJob</name>
    <message>
        <source>Saving %1</source>
        <translation>正在保存 %1</translation>
    </message>
    <message>
        <source>%1: unknown log format</source>
        <translation>%1：未知的日志文件格式</translation>
    </message>
    <message>
        <source>%1: cannot write format &apos;%2&apos;</source>
        <translation>%1：无法写入格式“%2”</translation>
    </message>
</context>
<context>
    <name>OdTreeModel</name>
    <message>
        <source>sub %1</source>
        <translation>子索引 %1</translation>
    </message>
    <message>
        <source>reading…</source>
        <translation>读取中…</translation>
    </message>
    <message>
        <source>writing…</source>
        <translation>写入中…</translation>
    </message>
    <message>
        <source>, PDO-mappable</source>
        <translation>，可映射到 PDO</translation>
    </message>
    <message>
        <source>
Limits: %1 … %2</source>
        <translation>
范围：%1 … %2</translation>
    </message>
    <message>
        <source>
Differs from the default</source>
        <translation>
与默认值不同</translation>
    </message>
    <message>
        <source>node %1 %2: %3</source>
        <translation>节点 %1 %2：%3</translation>
    </message>
    <message>
        <source>node %1 %2: %3 (bytes %4)</source>
        <translation>节点 %1 %2：%3（字节 %4）</translation>
    </message>
    <message>
        <source>
Bits on: %1</source>
        <translation>
已置位的位：%1</translation>
    </message>
</context>
<context>
    <name>OpenFailure</name>
    <message>
        <source>Open log</source>
        <translation>打开日志文件</translation>
    </message>
    <message>
        <source>%1 could not be opened as a CAN log.</source>
        <translation>无法将 %1 作为 CAN 日志文件打开。</translation>
    </message>
    <message>
        <source>Nothing was changed: the trace, nodes and signals shown are kept.</source>
        <translation>没有任何更改：当前显示的跟踪、节点与信号都保留。</translation>
    </message>
    <message>
        <source>Reading %1 stopped at an error.</source>
        <translation>读取 %1 时因错误而停止。</translation>
    </message>
    <message>
        <source>The %L1 frames read before it are shown.</source>
        <translation>显示错误之前读到的 %L1 帧。</translation>
    </message>
</context>
<context>
    <name>PdoDbcExport</name>
    <message>
        <source>%1: cannot write the DBC file (%2)</source>
        <translation>%1：无法写入 DBC 文件（%2）</translation>
    </message>
    <message>
        <source>PDO layout exported to %1: %2 PDO messages, %3 raw signals</source>
        <translation>PDO 配置已导出至 %1：%2 个 PDO 报文，%3 个原始信号</translation>
    </message>
    <message>
        <source>Export PDO layout as DBC</source>
        <translation>将 PDO 配置导出为 DBC</translation>
    </message>
    <message>
        <source>DBC file (*.dbc)</source>
        <translation>DBC 文件（*.dbc）</translation>
    </message>
    <message>
        <source>Exporting the PDO layout</source>
        <translation>正在导出 PDO 配置</translation>
    </message>
</context>
<context>
    <name>PdoVendorNotes</name>
    <message>
        <source>Delta ASDA-A2: the drive speaks standard CANopen only when P1-01 (2101h) = 0x0C; check it first.</source>
        <translation>台达 ASDA-A2：只有在 P1-01（2101h）= 0x0C 时，驱动器才使用标准 CANopen；请先检查此参数。</translation>
    </message>
    <message>
        <source>Delta writes every P-parameter (2000h–2FFFh) to EEPROM on each SDO write; P-parameters written by PDO are stored only when P3-11 X = 1 (wears the EEPROM).</source>
        <translation>台达每次以 SDO 写入 P 参数（2000h–2FFFh）都会写入 EEPROM；以 PDO 写入的 P 参数只有在 P3-11 X = 1 时才会保存（会耗损 EEPROM）。</translation>
    </message>
    <message>
        <source>At most 8 objects per PDO. Two PDOs with the same COB-ID within 1 ms raise alarm AL112.</source>
        <translation>每个 PDO 最多 8 个对象。两个 PDO 在 1 ms 内使用相同的 COB-ID 会触发报警 AL112。</translation>
    </message>
    <message>
        <source>RPDOs with a transmission type 0–240 act at the next SYNC: the master must send SYNC every cycle.</source>
        <translation>传输类型 0–240 的 RPDO 在下一个 SYNC 生效：主站必须在每个周期发送 SYNC。</translation>
    </message>
    <message>
        <source>AIMOTOR: CiA 402 objects act only when H02-00 (2002h:01) = 8 (CANopen control).</source>
        <translation>AIMOTOR：只有在 H02-00（2002h:01）= 8（CANopen 控制）时，CiA 402 对象才会生效。</translation>
    </message>
    <message>
        <source>AIMOTOR&apos;s default PDOs are synchronous (type 1): they are sent or applied only when a SYNC arrives. Start a SYNC producer, or choose an event-driven type.</source>
        <translation>AIMOTOR 的默认 PDO 为同步型（类型 1）：只有收到 SYNC 时才会发送或应用。请启动 SYNC 生产者，或改选事件触发类型。</translation>
    </message>
    <message>
        <source>Only CiA 402 objects (6000h–6FFFh) can be mapped; at most 8 objects per PDO.</source>
        <translation>只能映射 CiA 402 对象（6000h–6FFFh）；每个 PDO 最多 8 个对象。</translation>
    </message>
    <message>
        <source>DEXMART DEV: the COB-ID is read-only, so a PDO cannot be switched off while it is remapped: the mapping changes while the message is in use.</source>
        <translation>DEXMART DEV：COB-ID 为只读，重新映射时无法关闭 PDO：映射会在报文使用中更改。</translation>
    </message>
    <message>
        <source>At most 8 objects per PDO. The power-on mapping comes from parameter 09-26; a change made here is lost at power-off unless stored.</source>
        <translation>每个 PDO 最多 8 个对象。上电时的映射来自参数 09-26；在此所做的更改若未保存，断电后就会丢失。</translation>
    </message>
    <message>
        <source>Two motors: the M1/M2 values live in the Multi-Drive objects (3046h status, 3051h commands).</source>
        <translation>两台电机：M1/M2 的值位于 Multi-Drive 对象中（3046h 状态，3051h 命令）。</translation>
    </message>
    <message>
        <source>No dictionary is known for this node: objects cannot be offered by name. Scan the node (Nodes dock) or assign a dictionary first.</source>
        <translation>此节点没有已知的字典：无法按名称列出对象。请先扫描节点（节点面板）或指定字典。</translation>
    </message>
    <message>
        <source>The drive did not answer in time. Check that it is powered, that its node-ID is right, and the cable, termination and bit rate.</source>
        <translation>驱动器未及时响应。请确认它已通电、节点 ID 正确，并检查缆线、终端电阻与波特率。</translation>
    </message>
    <message>
        <source>The drive does not allow this object in a PDO. Take another object, or check the manual&apos;s &quot;PDO&quot; column for it.</source>
        <translation>驱动器不允许将此对象放入 PDO。请改选其他对象，或查阅手册中该对象的“PDO”列。</translation>
    </message>
    <message>
        <source>Too much data for one PDO on this drive: use fewer objects or smaller ones (at most 64 bits; some drives allow at most 8 objects).</source>
        <translation>此驱动器的单一 PDO 数据过多：请减少对象或改用较短的对象（最多 64 位；部分驱动器每个 PDO 最多 8 个对象）。</translation>
    </message>
    <message>
        <source>The drive reports a general parameter incompatibility: check that the PDO number exists and the values fit together.</source>
        <translation>驱动器报告一般性参数不兼容：请确认此 PDO 编号存在，且各数值彼此相符。</translation>
    </message>
    <message>
        <source>This parameter is read-only on this drive (some drives fix the COB-ID). Keep the current value.</source>
        <translation>此参数在此驱动器上为只读（部分驱动器的 COB-ID 固定）。请保留当前的值。</translation>
    </message>
    <message>
        <source>The drive does not have this object: this PDO number may not exist on it.</source>
        <translation>驱动器没有此对象：它可能没有这个编号的 PDO。</translation>
    </message>
    <message>
        <source>The drive refused the value: check the allowed range (transmission type, inhibit time, event timer).</source>
        <translation>驱动器拒绝此值：请检查允许的范围（传输类型、禁止时间、事件计时器）。</translation>
    </message>
    <message>
        <source>The drive does not accept this in its present state. It must be pre-operational (the wizard sends that first)</source>
        <translation>驱动器在当前状态下不接受此操作。它必须处于预操作状态（向导会先发送此命令）</translation>
    </message>
    <message>
        <source>Look up abort code 0x%1 in the drive&apos;s manual.</source>
        <translation>请在驱动器手册中查找中止码 0x%1。</translation>
    </message>
    <message>
        <source>The values read back differ from those written: the drive may have adjusted or ignored one. Read the PDO again and compare.</source>
        <translation>读回的值与写入的不同：驱动器可能调整或忽略了其中一个。请重新读取 PDO 并比较。</translation>
    </message>
    <message>
        <source>Sent at the next SYNC after a value changed (synchronous acyclic, type 0)</source>
        <translation>值变化后在下一个 SYNC 发送（同步非周期，类型 0）</translation>
    </message>
    <message>
        <source>Applied at the next SYNC (synchronous, type 0)</source>
        <translation>在下一个 SYNC 应用（同步，类型 0）</translation>
    </message>
    <message>
        <source>Sent on every SYNC (synchronous cyclic, type 1)</source>
        <translation>每个 SYNC 都发送（同步周期，类型 1）</translation>
    </message>
    <message>
        <source>Applied at the next SYNC (synchronous, type 1)</source>
        <translation>在下一个 SYNC 应用（同步，类型 1）</translation>
    </message>
    <message>
        <source>Sent once every %1 SYNCs (synchronous cyclic, type %1)</source>
        <translation>每 %1 个 SYNC 发送一次（同步周期，类型 %1）</translation>
    </message>
    <message>
        <source>Applied at the next SYNC (synchronous, type %1)</source>
        <translation>在下一个 SYNC 应用（同步，类型 %1）</translation>
    </message>
    <message>
        <source>Sampled at SYNC, sent only when asked for (RTR-only synchronous, type 252)</source>
        <translation>在 SYNC 采样，仅在被请求时发送（仅 RTR 同步，类型 252）</translation>
    </message>
    <message>
        <source>Sent only when asked for (RTR-only event-driven, type 253)</source>
        <translation>仅在被请求时发送（仅 RTR 事件触发，类型 253）</translation>
    </message>
    <message>
        <source>Sent when a value changes and/or every event-timer period (event-driven, type %1)</source>
        <translation>值变化时和／或每个事件计时器周期发送（事件触发，类型 %1）</translation>
    </message>
    <message>
        <source>Applied as soon as it arrives (event-driven, type %1)</source>
        <translation>收到后立即应用（事件触发，类型 %1）</translation>
    </message>
    <message>
        <source>Reserved transmission type %1</source>
        <translation>保留的传输类型 %1</translation>
    </message>
</context>
<context>
    <name>ProjectProgram</name>
    <message>
        <source>Download the project&apos;s program</source>
        <translation>下载项目的程序</translation>
    </message>
    <message>
        <source>The project&apos;s program of node %1 is not there: %2</source>
        <translation>找不到项目中节点 %1 的程序：%2</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Decoding the PDOs with the assigned dictionaries</source>
        <translation>正在以指定的字典解码 PDO</translation>
    </message>
    <message>
        <source>Fault reset (transition 15): clears the fault once its cause is removed. Sends controlword 6040h = 0000h, then 0080h (bit 7 rising). Expect Switch on disabled: fault bit 3 off, bit 6 on.</source>
        <translation>故障复位（转换 15）：在故障原因排除后清除故障。发送控制字 6040h = 0000h，接着 0080h（位 7 上升沿）。预期进入伺服无故障（Switch on disabled）：故障位 3 为 0，位 6 为 1。</translation>
    </message>
    <message>
        <source>Shutdown (transition 2): gets the drive ready, the motor stays without power. Sends 6040h = 0006h. Expect Ready to switch on: bits 0 and 5 on, bit 6 off.</source>
        <translation>关闭（Shutdown，转换 2）：让驱动器准备就绪，电机仍不通电。发送 6040h = 0006h。预期进入伺服准备好（Ready to switch on）：位 0 与 5 为 1，位 6 为 0。</translation>
    </message>
    <message>
        <source>Switch on (transition 3): switches the power stage on, the motor is not yet energised; needs main power. Sends 6040h = 0007h. Expect Switched on: bits 0, 1, 4 (voltage enabled) and 5 on.</source>
        <translation>接通主回路（Switch on，转换 3）：打开功率级，电机尚未通电；需要主电源。发送 6040h = 0007h。预期进入等待打开使能（Switched on）：位 0、1、4（电压已启用）与 5 为 1。</translation>
    </message>
    <message>
        <source>Enable operation (transition 4): energises the motor, which then holds its position and follows commands. Sends 6040h = 000Fh. Expect Operation enabled: bits 0, 1, 2 and 5 on.</source>
        <translation>使能运行（Enable operation，转换 4）：电机通电，保持位置并按命令动作。发送 6040h = 000Fh。预期进入伺服已使能（Operation enabled）：位 0、1、2 与 5 为 1。</translation>
    </message>
    <message>
        <source>booting (boot-up)</source>
        <translation>启动中（boot-up）</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>running (operational)</source>
        <translation>运行中（操作状态）</translation>
    </message>
    <message>
        <source>ready (pre-operational)</source>
        <translation>就绪（预操作状态）</translation>
    </message>
    <message>
        <source>seen</source>
        <translation>已检测</translation>
    </message>
</context>
<context>
    <name>SdoGroupIndex</name>
    <message>
        <source>SDO read node %1 %2</source>
        <extracomment>Trace, one row per SDO transfer: %1 = node, %2 = object (&quot;6041:00 Statusword&quot;)</extracomment>
        <translation>SDO 读取 节点 %1 %2</translation>
    </message>
    <message>
        <source>SDO write node %1 %2</source>
        <translation>SDO 写入 节点 %1 %2</translation>
    </message>
    <message>
        <source>block</source>
        <translation>块</translation>
    </message>
    <message>
        <source>segmented</source>
        <translation>分段</translation>
    </message>
    <message>
        <source>expedited</source>
        <translation>加速</translation>
    </message>
    <message>
        <source>1 frame</source>
        <translation>1 帧</translation>
    </message>
    <message>
        <source>%1 frames</source>
        <translation>%1 帧</translation>
    </message>
    <message>
        <source>: aborted 0x%1 %2 (%3, %4)</source>
        <extracomment>%1 = abort code in hex, %2 = its meaning, %3 = expedited/segmented/block, %4 = &quot;3 frames&quot;</extracomment>
        <translation>：已中止 0x%1 %2（%3，%4）</translation>
    </message>
    <message>
        <source> (%1, %2 bytes, %3)</source>
        <extracomment>%1 = expedited/segmented/block, %2 = size, %3 = &quot;3 frames&quot;</extracomment>
        <translation>（%1，%2 字节，%3）</translation>
    </message>
</context>
<context>
    <name>TraceFilter</name>
    <message>
        <source>filter: &apos;%1&apos; is not a node-ID (0-127)</source>
        <translation>筛选：“%1”不是节点 ID（0-127）</translation>
    </message>
    <message>
        <source>filter: &apos;node:&apos; needs node-IDs, e.g. node:5,6</source>
        <translation>筛选：“node:”需要节点 ID，例如 node:5,6</translation>
    </message>
    <message>
        <source>filter: unknown service &apos;%1&apos; (NMT SYNC TIME EMCY TPDO1..4 RPDO1..4 SDO_REQ SDO_RESP NMT_EC LSS_REQ LSS_RESP, or sdo, pdo)</source>
        <translation>筛选：未知的服务“%1”（NMT SYNC TIME EMCY TPDO1..4 RPDO1..4 SDO_REQ SDO_RESP NMT_EC LSS_REQ LSS_RESP，或 sdo、pdo）</translation>
    </message>
    <message>
        <source>filter: &apos;svc:&apos; needs service names, e.g. svc:sdo,emcy</source>
        <translation>筛选：“svc:”需要服务名称，例如 svc:sdo,emcy</translation>
    </message>
    <message>
        <source>filter: &apos;%1&apos; is not a COB-ID or range in hex (e.g. 580-5FF)</source>
        <translation>筛选：“%1”不是十六进制的 COB-ID 或范围（例如 580-5FF）</translation>
    </message>
    <message>
        <source>filter: &apos;id:&apos; needs COB-IDs in hex, e.g. id:580-5FF</source>
        <translation>筛选：“id:”需要十六进制的 COB-ID，例如 id:580-5FF</translation>
    </message>
    <message>
        <source>Grouping SDO transfers</source>
        <translation>正在将 SDO 传输分组</translation>
    </message>
    <message>
        <source>Filtering</source>
        <translation>筛选中</translation>
    </message>
</context>
<context>
    <name>TraceFind</name>
    <message>
        <source>Finding &apos;%1&apos;</source>
        <translation>正在查找“%1”</translation>
    </message>
</context>
<context>
    <name>WizardButtons</name>
    <message>
        <source>&lt; &amp;Back</source>
        <extracomment>A wizard&apos;s button to the previous step</extracomment>
        <translation>&lt; 上一步(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Next &gt;</source>
        <extracomment>A wizard&apos;s button to the next step</extracomment>
        <translation>下一步(&amp;N) &gt;</translation>
    </message>
</context>
<context>
    <name>WizardFramesPane</name>
    <message>
        <source>Time (s)</source>
        <translation>时间（秒）</translation>
    </message>
    <message>
        <source>Dir</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>数据</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>含义</translation>
    </message>
</context>
<context>
    <name>WizardMenu</name>
    <message>
        <source>Baud rate and node-ID…</source>
        <translation>波特率与节点 ID…</translation>
    </message>
    <message>
        <source>CiA 402 enable step-through…</source>
        <translation>CiA 402 逐步使能…</translation>
    </message>
    <message>
        <source>PDO mapping…</source>
        <translation>PDO 映射…</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ApplyDialog</name>
    <message>
        <source>Apply the project</source>
        <translation>应用项目</translation>
    </message>
    <message>
        <source>&amp;Apply</source>
        <translation>应用(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Store in the drives…</source>
        <translation>保存到驱动器(&amp;S)…</translation>
    </message>
    <message>
        <source>Save &amp;report…</source>
        <translation>保存报告(&amp;R)…</translation>
    </message>
    <message>
        <source>Connect to the machine&apos;s bus first (not listen-only).</source>
        <translation>请先连接到机器的总线（非仅监听）。</translation>
    </message>
    <message>
        <source>Reading the drives&apos; values (dry run)…</source>
        <translation>正在读取驱动器的值（模拟运行）…</translation>
    </message>
    <message>
        <source>Dry run: the SDO writes per node</source>
        <translation>模拟运行：各节点的 SDO 写入</translation>
    </message>
    <message>
        <source>The drives already hold the project&apos;s values: nothing to write.</source>
        <translation>驱动器已是项目的值：无需写入。</translation>
    </message>
    <message numerus="yes">
        <source>%n object(s) to write to %1 node(s). Check the writes below, then Apply.</source>
        <translation>
            <numerusform>要写入 %1 个节点的 %n 个对象。请检查下列写入，再按“应用”。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Write %n object(s) to the drives as listed? The first refused write stops; that node&apos;s old values are put back.</source>
        <translation>
            <numerusform>要按列表把 %n 个对象写入驱动器吗？第一个被拒绝的写入会停止，该节点的旧值会写回。</numerusform>
        </translation>
    </message>
    <message>
        <source>Writing…</source>
        <translation>正在写入…</translation>
    </message>
    <message>
        <source>Node %1 is a new drive (serial number 0x%2): the project now expects it.</source>
        <translation>节点 %1 是新的驱动器（序列号 0x%2）：项目现在以它为准。</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <source>The project was applied. The drives lose these values at power off unless they are stored.</source>
        <translation>项目已应用。除非保存，驱动器断电后会丢失这些值。</translation>
    </message>
    <message>
        <source>The project was not applied in full: see the result below.</source>
        <translation>项目未完整应用：请见下方结果。</translation>
    </message>
    <message>
        <source>Store in the drives</source>
        <translation>保存到驱动器</translation>
    </message>
    <message numerus="yes">
        <source>Save all parameters in the non-volatile memory of %n drive(s) (1010h:01 = &quot;save&quot;)?</source>
        <translation>
            <numerusform>要把全部参数保存到 %n 台驱动器的非易失性存储器吗（1010h:01 = &quot;save&quot;）？</numerusform>
        </translation>
    </message>
    <message>
        <source>stored: %1</source>
        <translation>已保存：%1</translation>
    </message>
    <message>
        <source>NOT stored: %1</source>
        <translation>未保存：%1</translation>
    </message>
    <message>
        <source>The parameters are stored in the drives.</source>
        <translation>参数已保存在驱动器中。</translation>
    </message>
    <message>
        <source>A drive did not store its parameters: see below.</source>
        <translation>有驱动器未保存参数：请见下方。</translation>
    </message>
    <message>
        <source>Save report</source>
        <translation>保存报告</translation>
    </message>
    <message>
        <source>Text files (*.txt);;All files (*)</source>
        <translation>文本文件 (*.txt);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>Report saved to %1</source>
        <translation>报告已保存到 %1</translation>
    </message>
</context>
<context>
    <name>coscope::gui::BusLossAdvice</name>
    <message>
        <source>NMT state unknown</source>
        <translation>NMT 状态未知</translation>
    </message>
    <message>
        <source>NMT: %1</source>
        <translation>NMT：%1</translation>
    </message>
    <message>
        <source>Bus lost (%1). The wizard stopped: nothing more can be sent to node %2.</source>
        <translation>总线中断（%1）。向导已停止：无法再向节点 %2 发送任何报文。</translation>
    </message>
    <message>
        <source>Last known state: %1, %2.</source>
        <translation>最后已知状态：%1，%2。</translation>
    </message>
    <message>
        <source>The drive may still be enabled (and moving, if it was): only its own communication-loss reaction (6007h) or heartbeat consumer (1016h) stops it.</source>
        <translation>驱动器可能仍处于使能状态（若原本在运行，也可能仍在运行）：只有它自身的通信中断反应（6007h）或心跳消费者（1016h）才会让它停下。</translation>
    </message>
    <message>
        <source>The drive was not enabled by this wizard; it should still be in that state.</source>
        <translation>此向导没有使能驱动器；它应仍保持原来的状态。</translation>
    </message>
    <message>
        <source>Check at the drive (display, enable LED, brake) before going near the machine. CoScope reconnects by itself; press “Read state” when the bus is back.</source>
        <translation>靠近机台前，请先在驱动器上确认（显示屏、使能指示灯、抱闸）。CoScope 会自动重新连接；总线恢复后请按“读取状态”。</translation>
    </message>
    <message>
        <source>Stopped: bus lost (%1) during step %2 of %3. The steps before it were sent; this one may or may not have reached the device, nothing after it was sent. The device may be half-configured (a PDO left disabled, a new node-ID or bit rate stored but not applied). When the bus is back, read the objects of this script back before running it again.</source>
        <translation>已停止：第 %2 步（共 %3 步）执行时总线中断（%1）。之前的步骤都已发送；这一步不一定已送达设备，之后的步骤都没有发送。设备可能只配置了一半（某个 PDO 仍被禁用，或新的节点 ID、波特率已保存但尚未生效）。总线恢复后，请先读回此脚本涉及的对象，再重新执行。</translation>
    </message>
    <message>
        <source>Stopped: bus lost (%1) while applying %2 of node %3 (last known %4). The PDO may be left disabled (COB-ID bit 31 set) with its mapping half written, and the node pre-operational. When the bus is back, read %2 back (Choose page) and apply again; the drive&apos;s own communication-loss reaction decides what it does meanwhile.</source>
        <translation>已停止：应用节点 %3 的 %2 时总线中断（%1）（最后已知：%4）。该 PDO 可能仍被禁用（COB-ID 第 31 位为 1），映射只写入一半，节点停在预操作状态。总线恢复后，请读回 %2（选择页）并重新应用；在此期间驱动器如何动作，取决于它自身的通信中断反应。</translation>
    </message>
    <message>
        <source>Stopped: bus lost (%1) during the change of node %2 (last known %3). The device may have taken the new node-ID or bit rate, stored it without applying it, or kept the old one. When the bus is back, scan (and if nothing answers, connect at the other bit rate) to see where the device is before changing anything else.</source>
        <translation>已停止：更改节点 %2 时总线中断（%1）（最后已知：%3）。设备可能已采用新的节点 ID 或波特率、已保存但尚未生效，或仍保留旧值。总线恢复后，请先扫描（若无响应，改用另一个波特率连接），确认设备当前的设置，再做其他更改。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::BusStatusBar</name>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Restart controller</source>
        <translation>重新启动控制器</translation>
    </message>
    <message>
        <source>The controller went bus-off and sends nothing; restart it (check wiring, termination and bit rate first)</source>
        <translation>控制器已进入总线关闭（bus-off），不再发送任何帧；请重新启动它（请先检查配线、终端电阻与比特率）</translation>
    </message>
    <message>
        <source>No source</source>
        <translation>无来源</translation>
    </message>
    <message>
        <source>Offline</source>
        <translation>离线</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>%L1 frames</source>
        <translation>%L1 帧</translation>
    </message>
    <message>
        <source> · listen-only</source>
        <translation> · 仅监听</translation>
    </message>
    <message>
        <source>%L1 frames/s</source>
        <translation>%L1 帧/秒</translation>
    </message>
    <message>
        <source>load %1 %</source>
        <translation>负载 %1 %</translation>
    </message>
    <message>
        <source>Estimated from frame lengths with worst-case bit stuffing at %1 bit/s</source>
        <translation>按帧长度估算，以最坏情况的位填充、%1 bit/s 计算</translation>
    </message>
    <message>
        <source>dropped %L1</source>
        <translation>丢失 %L1</translation>
    </message>
    <message>
        <source>errors %L1</source>
        <translation>错误 %L1</translation>
    </message>
    <message>
        <source>error active</source>
        <translation>错误主动</translation>
    </message>
    <message>
        <source>error warning</source>
        <translation>错误警告</translation>
    </message>
    <message>
        <source>error passive</source>
        <translation>错误被动</translation>
    </message>
    <message>
        <source>bus-off</source>
        <translation>总线关闭</translation>
    </message>
    <message>
        <source> · TEC %1 REC %2</source>
        <translation> · TEC %1 REC %2</translation>
    </message>
    <message>
        <source>CAN controller state from the last error frame (transmit / receive error counters)</source>
        <translation>取自最近一个错误帧的 CAN 控制器状态（发送／接收错误计数器）</translation>
    </message>
    <message>
        <source>Controller restarted after bus-off</source>
        <translation>控制器已在总线关闭后重新启动</translation>
    </message>
    <message>
        <source>Restart after bus-off failed: %1</source>
        <translation>总线关闭后重新启动失败：%1</translation>
    </message>
    <message>
        <source>Last restart failed: %1</source>
        <translation>上次重新启动失败：%1</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>已关闭</translation>
    </message>
    <message>
        <source>opening</source>
        <translation>打开中</translation>
    </message>
    <message>
        <source>open</source>
        <translation>已打开</translation>
    </message>
    <message>
        <source>error</source>
        <translation>错误</translation>
    </message>
    <message>
        <source>lost, retrying now</source>
        <translation>已中断，正在重试</translation>
    </message>
    <message>
        <source>lost, retrying in %1 s</source>
        <translation>已中断，%1 秒后重试</translation>
    </message>
    <message>
        <source>Adapter lost: %1. The trace keeps everything; CoScope reopens the bus when it is back (Disconnect stops trying).</source>
        <translation>适配器中断：%1。跟踪保留所有已收到的帧；适配器恢复后 CoScope 会重新打开总线（按“断开连接”即停止重试）。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::CaptureSettingsDialog</name>
    <message>
        <source>Capture settings</source>
        <translation>捕获设置</translation>
    </message>
    <message>
        <source>Automatic (%1)</source>
        <translation>自动（%1）</translation>
    </message>
    <message>
        <source> days</source>
        <translation> 天</translation>
    </message>
    <message>
        <source>Trace memory budget:</source>
        <translation>跟踪内存上限：</translation>
    </message>
    <message>
        <source>Keep capture journals for:</source>
        <translation>捕获日志保留时间：</translation>
    </message>
    <message>
        <source>Keep capture journals up to:</source>
        <translation>捕获日志保留总量上限：</translation>
    </message>
    <message>
        <source>Capture journals are kept in %1. Older ones are removed at start and when these settings change; a journal being written or not yet offered for reopening is never removed.</source>
        <translation>捕获日志保存在 %1。较旧的日志会在启动时及这些设置更改时删除；正在写入或尚未提供重新打开的日志绝不会被删除。</translation>
    </message>
    <message>
        <source> MiB</source>
        <translation> MiB</translation>
    </message>
    <message>
        <source>The trace keeps at most this much in memory; older frames are read back from the capture journal when needed. 0 = automatic: a quarter of the memory, at most 4 GiB.</source>
        <translation>跟踪在内存中最多保留这么多；较旧的帧在需要时从捕获日志读回。0 = 自动：内存的四分之一，最多 4 GiB。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::CompareDialog</name>
    <message>
        <source>Machine and project</source>
        <translation>机器与项目</translation>
    </message>
    <message>
        <source>&amp;Only differences</source>
        <translation>只显示差异(&amp;O)</translation>
    </message>
    <message>
        <source>&amp;Compare again</source>
        <translation>再次比较(&amp;C)</translation>
    </message>
    <message>
        <source>Export &amp;HTML…</source>
        <translation>导出 &amp;HTML…</translation>
    </message>
    <message>
        <source>Export CS&amp;V…</source>
        <translation>导出 CS&amp;V…</translation>
    </message>
    <message>
        <source>&amp;Replace drive…</source>
        <translation>更换驱动器(&amp;R)…</translation>
    </message>
    <message>
        <source>&amp;Apply the project…</source>
        <translation>应用项目(&amp;A)…</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>Connect to the machine&apos;s bus first (not listen-only): the comparison reads the drives.</source>
        <translation>请先连接到机器的总线（非仅监听）：比较会读取驱动器。</translation>
    </message>
    <message>
        <source>Scanning the bus and reading the drives…</source>
        <translation>正在扫描总线并读取驱动器…</translation>
    </message>
    <message>
        <source>The machine is as in the project.</source>
        <translation>机器与项目一致。</translation>
    </message>
    <message numerus="yes">
        <source>%n object(s) differ; %1 node(s) not as in the project.</source>
        <translation>
            <numerusform>%n 个对象不同；%1 个节点与项目不符。</numerusform>
        </translation>
    </message>
    <message>
        <source>Export comparison as HTML</source>
        <translation>将比较结果导出为 HTML</translation>
    </message>
    <message>
        <source>Export comparison as CSV</source>
        <translation>将比较结果导出为 CSV</translation>
    </message>
    <message>
        <source>HTML files (*.html)</source>
        <translation>HTML 文件 (*.html)</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>Exported to %1</source>
        <translation>已导出到 %1</translation>
    </message>
    <message>
        <source>Replace drive</source>
        <translation>更换驱动器</translation>
    </message>
    <message>
        <source>Node %1 is another drive of the same type. Write the project&apos;s configuration of node %1 to it? The writes are shown first.</source>
        <translation>节点 %1 是另一台同型驱动器。要把项目中节点 %1 的配置写入它吗？会先列出写入内容。</translation>
    </message>
    <message>
        <source>Open the node-ID wizard</source>
        <translation>打开节点 ID 向导</translation>
    </message>
    <message>
        <source>Download the project&apos;s &amp;program…</source>
        <translation>下载项目的程序(&amp;P)…</translation>
    </message>
    <message>
        <source>Load the program (firmware) the project names for the selected node: CiA 302-3 program download</source>
        <translation>为选中的节点载入项目指定的程序（固件）：CiA 302-3 程序下载</translation>
    </message>
    <message>
        <source>Node %1 does not answer, and node %2 is a drive of the same type that the project does not have (a new drive at its factory node-ID?). Give it node-ID %1 with the node-ID wizard, then write the project&apos;s configuration of node %1 to it and compare again?</source>
        <translation>节点 %1 没有响应，而节点 %2 是项目中没有的同型驱动器（出厂节点 ID 的新驱动器？）。要用节点 ID 向导将它设为节点 ID %1，再写入项目中节点 %1 的配置并重新比较吗？</translation>
    </message>
    <message>
        <source>Node %1 does not answer. If a new drive of the same type is on the bus at another node-ID or without one, find it in the node-ID wizard (scan, or find a device without node-ID by LSS) and give it node-ID %1; then the project&apos;s configuration of node %1 is written to it and the machine compared again.</source>
        <translation>节点 %1 没有响应。若总线上有一台使用其他节点 ID 或没有节点 ID 的同型新驱动器，请在节点 ID 向导中找到它（扫描，或用 LSS 查找没有节点 ID 的设备）并设为节点 ID %1；之后会写入项目中节点 %1 的配置并重新比较机器。</translation>
    </message>
    <message>
        <source>Replacing node %1: give the new drive node-ID %1 in the node-ID wizard.</source>
        <translation>正在更换节点 %1：请在节点 ID 向导中将新驱动器设为节点 ID %1。</translation>
    </message>
    <message>
        <source>The new drive answers at node %1: the project&apos;s configuration of node %1 is written to it next.</source>
        <translation>新驱动器已在节点 %1 响应：接着将写入项目中节点 %1 的配置。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::CompareModel</name>
    <message>
        <source>same</source>
        <translation>相同</translation>
    </message>
    <message>
        <source>replaced (another serial number)</source>
        <translation>已更换（序列号不同）</translation>
    </message>
    <message>
        <source>different device</source>
        <translation>不同的设备</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>缺失</translation>
    </message>
    <message>
        <source>not in project</source>
        <translation>不在项目中</translation>
    </message>
    <message>
        <source>differs</source>
        <translation>不同</translation>
    </message>
    <message>
        <source>unreadable</source>
        <translation>无法读取</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>节点</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>对象</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Project</source>
        <translation>项目</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>驱动器</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>默认值</translation>
    </message>
    <message>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Software version</source>
        <translation>软件版本</translation>
    </message>
    <message>
        <source>Software identification</source>
        <translation>软件标识</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ConnectDialog</name>
    <message>
        <source>Connect to a CAN bus</source>
        <translation>连接到 CAN 总线</translation>
    </message>
    <message>
        <source>(recent connections)</source>
        <translation>（最近的连接）</translation>
    </message>
    <message>
        <source>Recent:</source>
        <translation>最近：</translation>
    </message>
    <message>
        <source>Virtual drives (sim://)</source>
        <translation>虚拟驱动器（sim://）</translation>
    </message>
    <message>
        <source>socketcand server (remote CAN)</source>
        <translation>socketcand 服务器（远程 CAN）</translation>
    </message>
    <message>
        <source>Qt CAN plugin: %1</source>
        <translation>Qt CAN 插件：%1</translation>
    </message>
    <message>
        <source>Replay a log file</source>
        <translation>回放日志文件</translation>
    </message>
    <message>
        <source>Backend:</source>
        <translation>后端：</translation>
    </message>
    <message>
        <source>Device:</source>
        <translation>设备：</translation>
    </message>
    <message>
        <source>No CAN interfaces found. A virtual one for trying: &lt;tt&gt;sudo modprobe vcan; sudo ip link add dev vcan0 type vcan; sudo ip link set vcan0 up&lt;/tt&gt;. A real adapter: &lt;tt&gt;sudo ip link set can0 up type can bitrate 500000&lt;/tt&gt;. Then choose the backend again.</source>
        <translation>找不到 CAN 接口。可先创建一个虚拟接口试用：&lt;tt&gt;sudo modprobe vcan; sudo ip link add dev vcan0 type vcan; sudo ip link set vcan0 up&lt;/tt&gt;。物理适配器：&lt;tt&gt;sudo ip link set can0 up type can bitrate 500000&lt;/tt&gt;。然后再选一次后端。</translation>
    </message>
    <message>
        <source>Bring up</source>
        <translation>启用接口</translation>
    </message>
    <message>
        <source>Host:</source>
        <translation>主机：</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>端口：</translation>
    </message>
    <message>
        <source>Channel:</source>
        <translation>通道：</translation>
    </message>
    <message>
        <source>Virtual drives on the in-process bus:</source>
        <translation>进程内总线上的虚拟驱动器：</translation>
    </message>
    <message>
        <source>Drive (dictionary)</source>
        <translation>驱动器（字典）</translation>
    </message>
    <message>
        <source>Node-ID</source>
        <translation>节点 ID</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <source>Log to replay</source>
        <translation>要回放的日志文件</translation>
    </message>
    <message>
        <source>Log:</source>
        <translation>日志文件：</translation>
    </message>
    <message>
        <source>1×</source>
        <translation>1×</translation>
    </message>
    <message>
        <source>10×</source>
        <translation>10×</translation>
    </message>
    <message>
        <source>100×</source>
        <translation>100×</translation>
    </message>
    <message>
        <source>As fast as possible</source>
        <translation>尽可能快</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>循环播放</translation>
    </message>
    <message>
        <source>Speed:</source>
        <translation>速度：</translation>
    </message>
    <message>
        <source>(adapter setting)</source>
        <translation>（适配器设置）</translation>
    </message>
    <message>
        <source>%L1 kbit/s</source>
        <translation>%L1 kbit/s</translation>
    </message>
    <message>
        <source>Bit rate:</source>
        <translation>波特率：</translation>
    </message>
    <message>
        <source>CAN FD</source>
        <translation>CAN FD</translation>
    </message>
    <message>
        <source>data %L1 Mbit/s</source>
        <translation>数据段 %L1 Mbit/s</translation>
    </message>
    <message>
        <source>Listen-only (never transmit)</source>
        <translation>仅监听（绝不发送）</translation>
    </message>
    <message>
        <source>Type or paste a bus URL, e.g. socketcan://can0?bitrate=500000</source>
        <translation>输入或粘贴总线 URL，例如 socketcan://can0?bitrate=500000</translation>
    </message>
    <message>
        <source>URL:</source>
        <translation>URL：</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>Listed by the plugin without finding an adapter</source>
        <translation>插件列出了此项，但未找到适配器</translation>
    </message>
    <message>
        <source>Could not bring the interface up: %1</source>
        <translation>无法启用接口：%1</translation>
    </message>
    <message>
        <source>%1 is down</source>
        <translation>%1 已停用</translation>
    </message>
    <message>
        <source>%1 is up (virtual CAN)</source>
        <translation>%1 已启用（虚拟 CAN）</translation>
    </message>
    <message>
        <source>%1 is up at %L2 kbit/s</source>
        <translation>%1 已启用，波特率 %L2 kbit/s</translation>
    </message>
    <message>
        <source>%1 is up</source>
        <translation>%1 已启用</translation>
    </message>
    <message>
        <source>, CAN FD data %L1 Mbit/s</source>
        <translation>，CAN FD 数据段 %L1 Mbit/s</translation>
    </message>
    <message>
        <source>, controller in error warning (TEC %1, REC %2)</source>
        <translation>，控制器处于错误警告（TEC %1，REC %2）</translation>
    </message>
    <message>
        <source>, controller error passive (TEC %1, REC %2)</source>
        <translation>，控制器处于错误被动（TEC %1，REC %2）</translation>
    </message>
    <message>
        <source>, controller is bus-off: check wiring, termination and bit rate</source>
        <translation>，控制器已总线关闭：请检查配线、终端电阻与波特率</translation>
    </message>
    <message>
        <source>, controller stopped</source>
        <translation>，控制器已停止</translation>
    </message>
    <message>
        <source>Unverified: the %1 plugin lists %2 without finding an adapter; connecting shows whether one is there.</source>
        <translation>未确认：%1 插件列出了 %2，但未找到适配器；连接后即可知道适配器是否存在。</translation>
    </message>
    <message>
        <source>To change its bit rate, run:</source>
        <translation>要更改其波特率，请运行：</translation>
    </message>
    <message>
        <source>Bring it up with:</source>
        <translation>以下列指令启用：</translation>
    </message>
    <message>
        <source>Change bit rate now</source>
        <translation>立即更改波特率</translation>
    </message>
    <message>
        <source>Bring up now</source>
        <translation>立即启用</translation>
    </message>
    <message>
        <source>CoScope runs without the right to configure network interfaces: run the command above in a terminal</source>
        <translation>CoScope 没有设置网络接口的权限：请在终端中运行上面的指令</translation>
    </message>
    <message>
        <source>Choose at least one virtual drive</source>
        <translation>请至少选择一台虚拟驱动器</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ConsoleDock</name>
    <message>
        <source>Console</source>
        <translation>控制台</translation>
    </message>
</context>
<context>
    <name>coscope::gui::DcfApplyDialog</name>
    <message>
        <source>Apply DCF to node %1</source>
        <translation>将 DCF 应用到节点 %1</translation>
    </message>
    <message>
        <source>Nothing to write: every value of %1 is already on node %2 or cannot be written (%3 entries, listed below).</source>
        <translation>没有需要写入的项目：%1 的每个值都已与节点 %2 相同，或无法写入（%3 个项目，列于下方）。</translation>
    </message>
    <message>
        <source>Write %1 object(s) from &lt;b&gt;%2&lt;/b&gt; to &lt;b&gt;node %3&lt;/b&gt; over SDO? Each write is sent once; a refused write is reported and the others continue. %4 entries are not written (greyed).</source>
        <translation>要通过 SDO 将 &lt;b&gt;%2&lt;/b&gt; 的 %1 个对象写入 &lt;b&gt;节点 %3&lt;/b&gt; 吗？每次写入只发送一次；被拒绝的写入会报告，其余照常进行。有 %4 个项目不会写入（灰色显示）。</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>对象</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Write</source>
        <translation>写入</translation>
    </message>
    <message>
        <source>Node now / result</source>
        <translation>节点当前值／结果</translation>
    </message>
    <message>
        <source>(not read)</source>
        <translation>（未读取）</translation>
    </message>
    <message>
        <source>not written: %1</source>
        <translation>未写入：%1</translation>
    </message>
    <message>
        <source>Write %1 object(s)</source>
        <translation>写入 %1 个对象</translation>
    </message>
    <message>
        <source>written</source>
        <translation>已写入</translation>
    </message>
    <message>
        <source>Node %1: %2 of %3 write(s) done, %4 refused%5.</source>
        <translation>节点 %1：完成 %2／%3 次写入，%4 次被拒绝%5。</translation>
    </message>
    <message>
        <source>, cancelled before the rest</source>
        <translation>，其余在取消前未发送</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402FramesTabs</name>
    <message>
        <source>Frames (requests and responses)</source>
        <translation>帧（请求与响应）</translation>
    </message>
    <message>
        <source>Dry run (what will be sent)</source>
        <translation>模拟运行（将发送的内容）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402HomingBox</name>
    <message>
        <source>Method (6098h):</source>
        <translation>方式（6098h）：</translation>
    </message>
    <message>
        <source>Speed, search for switch (6099h:01):</source>
        <translation>速度，搜索开关（6099h:01）：</translation>
    </message>
    <message>
        <source>Speed, search for zero (6099h:02):</source>
        <translation>速度，搜索零点（6099h:02）：</translation>
    </message>
    <message>
        <source>Acceleration (609Ah):</source>
        <translation>加减速度（609Ah）：</translation>
    </message>
    <message>
        <source>Home offset (607Ch):</source>
        <translation>原点偏移（607Ch）：</translation>
    </message>
    <message>
        <source>Start homing…</source>
        <translation>开始原点回零…</translation>
    </message>
    <message>
        <source>Asks first. Then sets homing mode (6060h = 6), writes the values above, enables the drive and starts homing (6040h = 001Fh).</source>
        <translation>先询问。然后设置原点回零模式（6060h = 6）、写入上方的值、使能驱动器并开始原点回零（6040h = 001Fh）。</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Halts the homing on the drive&apos;s ramp (6040h = 010Fh); the drive stays enabled.</source>
        <translation>按驱动器的斜坡暂停原点回零（6040h = 010Fh）；驱动器保持使能。</translation>
    </message>
    <message>
        <source>home found</source>
        <translation>原点已找到</translation>
    </message>
    <message>
        <source>Not started.</source>
        <translation>尚未开始。</translation>
    </message>
    <message>
        <source>The homing&apos;s motion shows here</source>
        <translation>原点回零的运动显示在这里</translation>
    </message>
    <message>
        <source>Type a method number (-128 to 127) or choose one.</source>
        <translation>输入方式编号（-128 至 127）或从列表选择。</translation>
    </message>
    <message>
        <source>Not a homing method of the %1 (it has %2): it would be refused.</source>
        <translation>不是 %1 的回原点方式（它有 %2）：会被拒绝。</translation>
    </message>
    <message>
        <source>Not a CiA 402-2 homing method; the drive&apos;s own manual may define it.</source>
        <translation>不是 CiA 402-2 的回原点方式；驱动器自己的手册可能有定义。</translation>
    </message>
    <message>
        <source>(The drive&apos;s dictionary is not known: CiA 402-2&apos;s methods are listed.)</source>
        <translation>（不知道驱动器的字典：列出的是 CiA 402-2 的方式。）</translation>
    </message>
    <message>
        <source>Starting: homing mode, values, enable…</source>
        <translation>启动中：原点回零模式、数值、使能…</translation>
    </message>
    <message>
        <source>%1 s: statusword %2, position %3, velocity %4</source>
        <translation>%1 秒：状态字 %2，位置 %3，速度 %4</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402ModeBox</name>
    <message>
        <source>Mode of operation (6060h / 6061h)</source>
        <translation>运行模式（6060h / 6061h）</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>未读取</translation>
    </message>
    <message>
        <source>Set and verify</source>
        <translation>设置并验证</translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation>模式：</translation>
    </message>
    <message>
        <source>Shown by the drive (6061h): not read</source>
        <translation>驱动器显示（6061h）：未读取</translation>
    </message>
    <message>
        <source>Shown by the drive (6061h): %1</source>
        <translation>驱动器显示（6061h）：%1</translation>
    </message>
    <message>
        <source>Shown by the drive (6061h): %1 ✓</source>
        <translation>驱动器显示（6061h）：%1 ✓</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402MotionPlot</name>
    <message>
        <source>position 6064h</source>
        <translation>位置 6064h</translation>
    </message>
    <message>
        <source>position 6064h: %1</source>
        <translation>位置 6064h：%1</translation>
    </message>
    <message>
        <source>velocity 606Ch</source>
        <translation>速度 606Ch</translation>
    </message>
    <message>
        <source>velocity 606Ch: %1</source>
        <translation>速度 606Ch：%1</translation>
    </message>
    <message>
        <source>The test move&apos;s motion shows here</source>
        <translation>测试运行的运动曲线显示于此</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402PositionMoveBox</name>
    <message>
        <source>Relative (6040h bit 6)</source>
        <translation>相对（6040h 位 6）</translation>
    </message>
    <message>
        <source>Target (607Ah):</source>
        <translation>目标（607Ah）：</translation>
    </message>
    <message>
        <source>Profile velocity (6081h):</source>
        <translation>轮廓速度（6081h）：</translation>
    </message>
    <message>
        <source>Acceleration (6083h):</source>
        <translation>轮廓加速度（6083h）：</translation>
    </message>
    <message>
        <source>Deceleration (6084h):</source>
        <translation>轮廓减速度（6084h）：</translation>
    </message>
    <message>
        <source>Arm position move…</source>
        <translation>准备位置移动…</translation>
    </message>
    <message>
        <source>Hold to move</source>
        <translation>按住移动</translation>
    </message>
    <message>
        <source>The motor moves only while this button is held down; releasing it halts the motor (6040h bit 8).</source>
        <translation>只有按住此按钮时电机才会移动；松开即暂停电机（6040h 位 8）。</translation>
    </message>
    <message>
        <source>6040h bit 4: new set-point</source>
        <translation>6040h 位 4：新设定点</translation>
    </message>
    <message>
        <source>6041h bit 12: set-point acknowledge</source>
        <translation>6041h 位 12：设定点确认</translation>
    </message>
    <message>
        <source>6041h bit 10: target reached</source>
        <translation>6041h 位 10：到达目标</translation>
    </message>
    <message>
        <source>6041h bit 13: following error</source>
        <translation>6041h 位 13：位置跟随超差</translation>
    </message>
    <message>
        <source>The move&apos;s motion shows here</source>
        <translation>移动的运动显示在这里</translation>
    </message>
    <message>
        <source>move by %1 (relative, 607Ah = %2) at up to %3 (6081h)</source>
        <translation>移动 %1（相对，607Ah = %2），速度最高 %3（6081h）</translation>
    </message>
    <message>
        <source>move to position %1 (absolute, 607Ah = %2) at up to %3 (6081h)</source>
        <translation>移动到位置 %1（绝对，607Ah = %2），速度最高 %3（6081h）</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>%1 of %2 → %3</source>
        <translation>%1（%2 → %3）</translation>
    </message>
    <message>
        <source>Set-point handshake: %1 new set-point (bit 4 = 1) → %2 acknowledged (bit 12), bit 4 = 0 → %3 target reached (bit 10)</source>
        <translation>设定点握手：%1 新设定点（位 4 = 1）→ %2 已确认（位 12），位 4 = 0 → %3 到达目标（位 10）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402StateDiagram</name>
    <message>
        <source>State not read yet</source>
        <translation>尚未读取状态</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402StatusPanel</name>
    <message>
        <source>Statusword (6041h): not read</source>
        <translation>状态字（6041h）：未读取</translation>
    </message>
    <message>
        <source>On: </source>
        <translation>开：</translation>
    </message>
    <message>
        <source>Off: </source>
        <translation>关：</translation>
    </message>
    <message>
        <source>Statusword (6041h) = %1 — %2</source>
        <translation>状态字（6041h）= %1 — %2</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402StepBar</name>
    <message>
        <source>Step through — one button per transition</source>
        <translation>逐步运行 — 每个状态转换一个按钮</translation>
    </message>
    <message>
        <source>1  Fault reset</source>
        <translation>1  故障复位</translation>
    </message>
    <message>
        <source>2  Shutdown</source>
        <translation>2  关闭（Shutdown）</translation>
    </message>
    <message>
        <source>3  Switch on</source>
        <translation>3  接通主回路（Switch on）</translation>
    </message>
    <message>
        <source>4  Enable operation…</source>
        <translation>4  使能运行（Enable operation）…</translation>
    </message>
    <message>
        <source>The drive is enabled (Operation enabled). Choose a mode and try a test move, or press Disable.</source>
        <translation>驱动器已使能（Operation enabled）。请选择模式并试做测试运行，或按“停用”。</translation>
    </message>
    <message>
        <source>Quick stop is active: press Disable to leave it (Disable voltage, transition 12).</source>
        <translation>Quick Stop 已启动：请按“停用”离开（Disable voltage，转换 12）。</translation>
    </message>
    <message>
        <source>Next: %1</source>
        <translation>下一步：%1</translation>
    </message>
    <message>
        <source>The drive is in %1; wait for it to settle, then read the state again.</source>
        <translation>驱动器处于 %1；请等它稳定后再读取一次状态。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402TestMoveBox</name>
    <message>
        <source>Test move (optional, small limits)</source>
        <translation>测试运行（选用，小范围限制）</translation>
    </message>
    <message>
        <source>Jog (profile velocity, 60FFh)</source>
        <translation>点动（profile velocity，60FFh）</translation>
    </message>
    <message>
        <source>Short move (profile position, 607Ah relative)</source>
        <translation>短距移动（profile position，607Ah 相对）</translation>
    </message>
    <message>
        <source>Kind:</source>
        <translation>类型：</translation>
    </message>
    <message>
        <source>Velocity:</source>
        <translation>速度：</translation>
    </message>
    <message>
        <source>Distance:</source>
        <translation>距离：</translation>
    </message>
    <message>
        <source> ms max</source>
        <translation> ms 上限</translation>
    </message>
    <message>
        <source>Time limit:</source>
        <translation>时间上限：</translation>
    </message>
    <message>
        <source>Arm test move…</source>
        <translation>准备测试运行…</translation>
    </message>
    <message>
        <source>Hold to run</source>
        <translation>按住运行</translation>
    </message>
    <message>
        <source>The motor moves only while this button is held down; releasing it stops the motor.</source>
        <translation>只有按住此按钮时电机才会运行；放开即停止电机。</translation>
    </message>
    <message>
        <source>turn at %1 (profile velocity, 60FFh = %2)</source>
        <translation>以 %1 转动（profile velocity，60FFh = %2）</translation>
    </message>
    <message>
        <source>move %1 at up to %2 (profile position, relative: 607Ah = %3, 6081h = %4)</source>
        <translation>移动 %1，速度最高 %2（profile position，相对：607Ah = %3，6081h = %4）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402Wizard</name>
    <message>
        <source>CiA 402 enable step-through</source>
        <translation>CiA 402 逐步使能</translation>
    </message>
    <message>
        <source>connection lost</source>
        <translation>连接中断</translation>
    </message>
    <message>
        <source>Connection lost (bus %1). The drive was told to disable if the bus still accepted it; otherwise its own communication-loss reaction (6007h) applies. Check the drive.</source>
        <translation>连接中断（总线 %1）。若总线仍可发送，已通知驱动器停用；否则由驱动器自身的通信中断处理（6007h）决定。请检查驱动器。</translation>
    </message>
    <message>
        <source>error</source>
        <translation>错误</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>已关闭</translation>
    </message>
    <message>
        <source>The connection changed. Choose the drive again.</source>
        <translation>连接已更改。请重新选择驱动器。</translation>
    </message>
    <message>
        <source>Listen-only connection: this wizard is disabled because it would have to send (SDO to 6040h/6041h).</source>
        <translation>仅监听连接：此向导必须发送（对 6040h/6041h 的 SDO），因此已停用。</translation>
    </message>
    <message>
        <source>wizard destroyed</source>
        <translation>向导已销毁</translation>
    </message>
    <message>
        <source>Drive (node):</source>
        <translation>驱动器（节点）：</translation>
    </message>
    <message>
        <source>Read state</source>
        <translation>读取状态</translation>
    </message>
    <message>
        <source>Drive state (CiA 402 state machine)</source>
        <translation>驱动器状态（CiA 402 状态机）</translation>
    </message>
    <message>
        <source>Statusword bits</source>
        <translation>状态字位</translation>
    </message>
    <message>
        <source>Saved %1; replay it with: coscope-cli script run BUS %1</source>
        <translation>已保存 %1；回放指令：coscope-cli script run BUS %1</translation>
    </message>
    <message>
        <source>Quick stop</source>
        <translation>快速停止</translation>
    </message>
    <message>
        <source>Brakes on the drive&apos;s quick stop ramp (6040h = 0002h).</source>
        <translation>按驱动器的 Quick Stop 减速曲线制动停止（6040h = 0002h）。</translation>
    </message>
    <message>
        <source>Disable</source>
        <translation>停用</translation>
    </message>
    <message>
        <source>Removes power from the motor: Shutdown then Disable voltage (6040h = 0006h, 0000h).</source>
        <translation>切断电机电源：先 Shutdown 再 Disable voltage（6040h = 0006h、0000h）。</translation>
    </message>
    <message>
        <source>Dry run</source>
        <translation>模拟运行</translation>
    </message>
    <message>
        <source>Show the exact SDO sequence of the enable, without sending anything.</source>
        <translation>显示使能过程完整的 SDO 顺序，不发送任何内容。</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>Not connected to a bus.</source>
        <translation>未连接到总线。</translation>
    </message>
    <message>
        <source>Listen-only connection: the wizard does not send.</source>
        <translation>仅监听连接：向导不会发送。</translation>
    </message>
    <message>
        <source>The bus is not open.</source>
        <translation>总线未打开。</translation>
    </message>
    <message>
        <source>No drive chosen.</source>
        <translation>尚未选择驱动器。</translation>
    </message>
    <message>
        <source>Node %1 is not being read: press “Read state” to read it again.</source>
        <translation>节点 %1 当前未被读取：请按“读取状态”重新读取。</translation>
    </message>
    <message>
        <source>Node %1 is not a CiA 402 drive.</source>
        <translation>节点 %1 不是 CiA 402 驱动器。</translation>
    </message>
    <message>
        <source>wizard closed</source>
        <translation>向导已关闭</translation>
    </message>
    <message>
        <source>Check main power, the enable and safe torque off (STO) inputs, and the drive&apos;s own display.</source>
        <translation>请检查主电源、使能与安全转矩关闭（STO）输入，以及驱动器本身的面板显示。</translation>
    </message>
    <message>
        <source>Wait for the current step to finish.</source>
        <translation>请等当前步骤完成。</translation>
    </message>
    <message>
        <source>Enable operation</source>
        <translation>运行使能</translation>
    </message>
    <message>
        <source>Enable operation energises the motor of node %1: it will hold its position and follow commands.

Make sure the machine is safe to move and people are clear.

Send 6040h = 000Fh now?</source>
        <translation>运行使能会让节点 %1 的电机通电：电机会保持位置并按命令动作。

请确认设备可以安全移动，且人员已离开。

现在发送 6040h = 000Fh？</translation>
    </message>
    <message>
        <source>Enable operation was not confirmed; nothing was sent.</source>
        <translation>未确认运行使能；没有发送任何内容。</translation>
    </message>
    <message>
        <source>%1: sending… (%2)</source>
        <translation>%1：发送中…（%2）</translation>
    </message>
    <message>
        <source>%1 done: the drive is now in %2 (statusword %3h).</source>
        <translation>%1 完成：驱动器当前处于 %2（状态字 %3h）。</translation>
    </message>
    <message>
        <source>Step “%1” failed: %2.</source>
        <translation>步骤“%1”失败：%2。</translation>
    </message>
    <message>
        <source>
The drive was sent Disable voltage (6040h = 0000h) and is now in %1.</source>
        <translation>
已对驱动器发送 Disable voltage（6040h = 0000h），当前处于 %1。</translation>
    </message>
    <message>
        <source>
DISABLING FAILED: %1</source>
        <translation>
停用失败：%1</translation>
    </message>
    <message>
        <source>What to check: </source>
        <translation>检查事项：</translation>
    </message>
    <message>
        <source>The drive does not list %1 as supported (6502h = %2h).</source>
        <translation>驱动器未列出支持 %1（6502h = %2h）。</translation>
    </message>
    <message>
        <source>Setting the mode of operation: 6060h = %1 (%2), then checking 6061h…</source>
        <translation>设置运行模式：6060h = %1（%2），接着检查 6061h…</translation>
    </message>
    <message>
        <source>Mode set and verified: the drive shows %1 in 6061h.</source>
        <translation>模式已设置并验证：驱动器在 6061h 显示 %1。</translation>
    </message>
    <message>
        <source>Could not set %1: %2</source>
        <translation>无法设置 %1：%2</translation>
    </message>
    <message>
        <source>Enable the drive first (Operation enabled), then arm the test move.</source>
        <translation>请先让驱动器使能（Operation enabled），再准备测试运行。</translation>
    </message>
    <message>
        <source>Test move</source>
        <translation>测试运行</translation>
    </message>
    <message>
        <source>While you hold “Hold to run”, the motor of node %1 will %2, for at most %3 ms.
Releasing the button stops it. Make sure the axis is free to move.

Arm the test move?</source>
        <translation>按住“按住运行”期间，节点 %1 的电机将%2，最长 %3 ms。
放开按钮即停止。请确认轴可以自由移动。

要准备测试运行吗？</translation>
    </message>
    <message>
        <source>Test move not armed.</source>
        <translation>未准备测试运行。</translation>
    </message>
    <message>
        <source>Test move armed: hold the “Hold to run” button to move, release it to stop.</source>
        <translation>测试运行已就绪：按住“按住运行”按钮即移动，放开即停止。</translation>
    </message>
    <message>
        <source>Arm the test move first.</source>
        <translation>请先准备测试运行。</translation>
    </message>
    <message>
        <source>Test move stopped: %1. The drive stays enabled; press Disable when done.</source>
        <translation>测试运行已停止：%1。驱动器保持使能；完成后请按“停用”。</translation>
    </message>
    <message>
        <source>Test move failed: %1</source>
        <translation>测试运行失败：%1</translation>
    </message>
    <message>
        <source>Moving while the button is held…</source>
        <translation>按住按钮期间运行中…</translation>
    </message>
    <message>
        <source>hold-to-run button released</source>
        <translation>已放开“按住运行”按钮</translation>
    </message>
    <message>
        <source>Quick stop: %1</source>
        <translation>快速停止：%1</translation>
    </message>
    <message>
        <source>Quick stop: sending 6040h = 0002h…</source>
        <translation>快速停止：发送 6040h = 0002h…</translation>
    </message>
    <message>
        <source>Quick stop done: the drive is in %1.</source>
        <translation>快速停止完成：驱动器处于 %1。</translation>
    </message>
    <message>
        <source>Disable: %1</source>
        <translation>停用：%1</translation>
    </message>
    <message>
        <source>Disabling: Shutdown, then Disable voltage…</source>
        <translation>停用中：先 Shutdown，再 Disable voltage…</translation>
    </message>
    <message>
        <source>The drive is disabled (%1): the motor has no power.</source>
        <translation>驱动器已停用（%1）：电机无电源。</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message numerus="yes">
        <source>Dry run: %n step(s) the enable would send from %1 — nothing was sent. “Save as script…” keeps them for coscope-cli script run.</source>
        <translation>
            <numerusform>模拟运行：使能进程将从 %1 起发送 %n 个步骤——实际上没有发送任何内容。“另存为脚本…”可保留这些步骤供 coscope-cli script run 使用。</numerusform>
        </translation>
    </message>
    <message>
        <source>Looking for a CiA 402 drive (device type 1000h = …0192h)…</source>
        <translation>查找 CiA 402 驱动器（设备类型 1000h = …0192h）…</translation>
    </message>
    <message>
        <source>No CiA 402 drive answered yet; trying again.</source>
        <translation>尚无 CiA 402 驱动器响应；重试中。</translation>
    </message>
    <message>
        <source>another drive was chosen</source>
        <translation>已选择另一台驱动器</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>Node %1 — %2</source>
        <translation>节点 %1 — %2</translation>
    </message>
    <message>
        <source>Reading the identity of node %1 (1018h)…</source>
        <translation>读取节点 %1 的识别信息（1018h）…</translation>
    </message>
    <message>
        <source>Node %1 is a %2: %3</source>
        <translation>节点 %1 是 %2：%3</translation>
    </message>
    <message>
        <source>The state of node %1 is not known: not connected.</source>
        <translation>节点 %1 的状态不明：未连接。</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>The drive is initialising (Not ready to switch on); waiting for Switch on disabled…</source>
        <translation>驱动器正在初始化（Not ready to switch on）；等待进入伺服无故障（Switch on disabled）…</translation>
    </message>
    <message>
        <source>The drive finished initialising.</source>
        <translation>驱动器已完成初始化。</translation>
    </message>
    <message>
        <source>Node %1 has no statusword 6041h: it is not a CiA 402 drive (%2).</source>
        <translation>节点 %1 没有状态字 6041h：它不是 CiA 402 驱动器（%2）。</translation>
    </message>
    <message>
        <source>Cannot read the drive&apos;s state: %1. Check that the drive is powered and connected, and its node-ID.</source>
        <translation>无法读取驱动器状态：%1。请确认驱动器已通电并已连接，以及其节点 ID 是否正确。</translation>
    </message>
    <message>
        <source>Error code 603Fh could not be read: %1</source>
        <translation>无法读取错误码 603Fh：%1</translation>
    </message>
    <message>
        <source>%1 is %2, not %3: the drive is not in CANopen control and will ignore the controlword. Set %1 = %3 first.</source>
        <translation>%1 为 %2，而非 %3：驱动器不在 CANopen 控制模式，会忽略控制字。请先将 %1 设为 %3。</translation>
    </message>
    <message>
        <source>Mode of operation (6061h): %1</source>
        <translation>运行模式（6061h）：%1</translation>
    </message>
    <message>
        <source>Bus lost. CoScope reconnects by itself; press “Read state” when the bus is back.</source>
        <translation>总线中断。CoScope 会自动重新连接；总线恢复后请按“读取状态”。</translation>
    </message>
    <message>
        <source>CiA 402 state unknown</source>
        <translation>CiA 402 状态未知</translation>
    </message>
    <message>
        <source>%1 (statusword %2h)</source>
        <translation>%1（状态字 %2h）</translation>
    </message>
    <message>
        <source>a state machine step</source>
        <translation>状态机步骤</translation>
    </message>
    <message>
        <source>the mode of operation is being changed</source>
        <translation>正在更改运行模式</translation>
    </message>
    <message>
        <source>The test move needs %1, which the drive does not list as supported (6502h): no test move in %2.</source>
        <translation>测试运行需要%1，但驱动器未将其列为支持的模式（6502h）：在%2下不进行测试运行。</translation>
    </message>
    <message>
        <source>Mode of operation</source>
        <translation>运行模式</translation>
    </message>
    <message>
        <source>The drive is in %1; the test move needs %2: switch the mode of operation (6060h = %3)?</source>
        <translation>驱动器当前为%1；测试运行需要%2：要切换运行模式（6060h = %3）吗？</translation>
    </message>
    <message>
        <source>Test move not armed: the mode of operation stays %1.</source>
        <translation>未准备测试运行：运行模式保持%1。</translation>
    </message>
    <message>
        <source>Test move armed: holding the “Hold to run” button first switches the mode of operation to %1, then moves; release it to stop.</source>
        <translation>测试运行已就绪：按住“按住运行”按钮时会先将运行模式切换为%1，然后移动；放开即停止。</translation>
    </message>
    <message>
        <source>The test move is no longer armed (%1): arm it again to move.</source>
        <translation>测试运行已不再就绪（%1）：需再次准备才能移动。</translation>
    </message>
    <message>
        <source>the test move failed</source>
        <translation>测试运行失败</translation>
    </message>
    <message>
        <source>the drive faulted</source>
        <translation>驱动器发生故障</translation>
    </message>
    <message>
        <source>the drive left Operation enabled</source>
        <translation>驱动器已离开伺服已使能（Operation enabled）</translation>
    </message>
    <message>
        <source>the mode of operation changed</source>
        <translation>运行模式已更改</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>原点回零</translation>
    </message>
    <message>
        <source>Position move</source>
        <translation>位置移动</translation>
    </message>
    <message>
        <source>The position move is no longer armed (%1): arm it again to move.</source>
        <translation>位置移动已不再就绪（%1）：需再次准备才能移动。</translation>
    </message>
    <message>
        <source>Test move limits: at most %1 per move, at most %2.</source>
        <translation>测试运行限制：每次最多 %1，速度最高 %2。</translation>
    </message>
    <message>
        <source>Software position limits (607Dh): %1 to %2.</source>
        <translation>软件限位（607Dh）：%1 至 %2。</translation>
    </message>
    <message>
        <source>No software position limits (607Dh) read.</source>
        <translation>未读到软件限位（607Dh）。</translation>
    </message>
    <message>
        <source>Type a homing method number (6098h) or choose one from the list.</source>
        <translation>输入回原点方式编号（6098h）或从列表选择。</translation>
    </message>
    <message>
        <source>Node %1 (%2) has no homing method %3: its methods are %4. Nothing was sent.</source>
        <translation>节点 %1（%2）没有回原点方式 %3：它的方式为 %4。未发送任何内容。</translation>
    </message>
    <message>
        <source>The drive does not list Homing as supported (6502h): it cannot home.</source>
        <translation>驱动器未列出支持原点回零（6502h）：无法回原点。</translation>
    </message>
    <message>
        <source>The drive is in %1; homing needs %2: switch the mode of operation (6060h = %3)?</source>
        <translation>驱动器当前为 %1；原点回零需要 %2：要切换运行模式（6060h = %3）吗？</translation>
    </message>
    <message>
        <source>Homing not started: the mode of operation stays %1.</source>
        <translation>未开始原点回零：运行模式保持 %1。</translation>
    </message>
    <message>
        <source>not a CiA 402-2 method</source>
        <translation>不是 CiA 402-2 的方式</translation>
    </message>
    <message>
        <source>The drive is enabled first (Operation enabled): the motor gets power.

</source>
        <translation>会先使能驱动器（Operation enabled）：电机将通电。

</translation>
    </message>
    <message>
        <source>Node %1 will home with method %2: %3.

%4The axis may travel to a limit switch, the home switch or an end stop: make sure it is free to move. Stop halts it at any time.

Start homing?</source>
        <translation>节点 %1 将以方式 %2 回原点：%3。

%4轴可能移动到限位开关、原点开关或机械极限位：请确认它可以自由移动。随时可按“停止”暂停。

开始原点回零？</translation>
    </message>
    <message>
        <source>Homing was not confirmed; nothing was sent.</source>
        <translation>未确认原点回零；未发送任何内容。</translation>
    </message>
    <message>
        <source>homing started</source>
        <translation>已开始原点回零</translation>
    </message>
    <message>
        <source>Homing node %1 with method %2…</source>
        <translation>节点 %1 以方式 %2 回原点中…</translation>
    </message>
    <message>
        <source>Stopping the homing: halt (6040h = 010Fh)…</source>
        <translation>正在停止原点回零：暂停（6040h = 010Fh）…</translation>
    </message>
    <message>
        <source>Stop pressed</source>
        <translation>已按下“停止”</translation>
    </message>
    <message>
        <source>not read (%1)</source>
        <translation>未读取（%1）</translation>
    </message>
    <message>
        <source>Homing attained (statusword %1): position actual 6064h = %2. The drive stays enabled.</source>
        <translation>原点回零完成（状态字 %1）：实际位置 6064h = %2。驱动器保持使能。</translation>
    </message>
    <message>
        <source>Homing stopped (%1) before home was set.</source>
        <translation>原点回零在设定原点前已停止（%1）。</translation>
    </message>
    <message>
        <source>Homing failed: %1</source>
        <translation>原点回零失败：%1</translation>
    </message>
    <message>
        <source>Enable the drive first (Operation enabled), then arm the position move.</source>
        <translation>请先让驱动器使能（Operation enabled），再准备位置移动。</translation>
    </message>
    <message>
        <source>Set a profile velocity (6081h) above 0.</source>
        <translation>请设置大于 0 的轮廓速度（6081h）。</translation>
    </message>
    <message>
        <source>The profile velocity is above the test move&apos;s limit of %1.</source>
        <translation>轮廓速度超过测试运行的限制 %1。</translation>
    </message>
    <message>
        <source>The drive does not list Profile position as supported (6502h): no position move.</source>
        <translation>驱动器未列出支持轮廓位置模式（6502h）：无法位置移动。</translation>
    </message>
    <message>
        <source>Reading the position (6064h) and the software limits (607Dh)…</source>
        <translation>正在读取位置（6064h）和软件限位（607Dh）…</translation>
    </message>
    <message>
        <source>Position move not armed: the position 6064h could not be read (%1).</source>
        <translation>位置移动未就绪：无法读取位置 6064h（%1）。</translation>
    </message>
    <message>
        <source>Position move not armed: the drive is no longer in Operation enabled.</source>
        <translation>位置移动未就绪：驱动器已不在 Operation enabled。</translation>
    </message>
    <message>
        <source>Position move not armed: %1 from the position now is more than the test move&apos;s limit of %2.</source>
        <translation>位置移动未就绪：距当前位置 %1，超过测试运行的限制 %2。</translation>
    </message>
    <message>
        <source>Position move not armed: it would end at %1, outside the software position limits 607Dh (%2 to %3).</source>
        <translation>位置移动未就绪：会停在 %1，超出软件限位 607Dh（%2 至 %3）。</translation>
    </message>
    <message>
        <source>The drive is in %1; the position move needs %2: switch the mode of operation (6060h = %3)?</source>
        <translation>驱动器当前为 %1；位置移动需要 %2：要切换运行模式（6060h = %3）吗？</translation>
    </message>
    <message>
        <source>Position move not armed: the mode of operation stays %1.</source>
        <translation>位置移动未就绪：运行模式保持 %1。</translation>
    </message>
    <message>
        <source>While you hold “Hold to move”, the motor of node %1 will %2.
Releasing the button halts it. Make sure the axis is free to move.

Arm the position move?</source>
        <translation>按住“按住移动”期间，节点 %1 的电机将%2。
松开按钮即暂停。请确认轴可以自由移动。

准备位置移动？</translation>
    </message>
    <message>
        <source>Position move not armed.</source>
        <translation>位置移动未就绪。</translation>
    </message>
    <message>
        <source>Position move armed: hold the “Hold to move” button to move, release it to halt.</source>
        <translation>位置移动已就绪：按住“按住移动”按钮即移动，松开即暂停。</translation>
    </message>
    <message>
        <source>Arm the position move first.</source>
        <translation>请先准备位置移动。</translation>
    </message>
    <message>
        <source>the move was changed after arming</source>
        <translation>准备后移动设置已更改</translation>
    </message>
    <message>
        <source>The position move was changed after it was armed: arm it again.</source>
        <translation>位置移动在准备后已更改：请再次准备。</translation>
    </message>
    <message>
        <source>The move would end outside the software position limits 607Dh: not started.</source>
        <translation>移动会停在软件限位 607Dh 之外：未开始。</translation>
    </message>
    <message>
        <source>Halted before the target (%1): position actual 6064h = %2, target %3. The drive stays enabled.</source>
        <translation>在到达目标前暂停（%1）：实际位置 6064h = %2，目标 %3。驱动器保持使能。</translation>
    </message>
    <message>
        <source>Target reached (statusword %1): position actual 6064h = %2.</source>
        <translation>已到达目标（状态字 %1）：实际位置 6064h = %2。</translation>
    </message>
    <message>
        <source>the position move failed</source>
        <translation>位置移动失败</translation>
    </message>
    <message>
        <source>Position move stopped (%1).</source>
        <translation>位置移动已停止（%1）。</translation>
    </message>
    <message>
        <source>Position move failed: %1</source>
        <translation>位置移动失败：%1</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ErrorControlDialog</name>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Heartbeat and guarding of node %1</source>
        <translation>节点 %1 的心跳与节点保护</translation>
    </message>
    <message>
        <source>How CoScope watches that node %1 is there (CiA 301 error control). A lost node is raised in the Events.</source>
        <translation>CoScope 如何监视节点 %1 是否在线（CiA 301 错误控制）。节点丢失时会记入事件。</translation>
    </message>
    <message>
        <source>Not watched</source>
        <translation>不监视</translation>
    </message>
    <message>
        <source>Heartbeat: the node sends it (1017h); lost when none comes within</source>
        <translation>心跳：由节点发送（1017h）；在以下时间内未收到即视为丢失</translation>
    </message>
    <message>
        <source>Consumer time:</source>
        <translation>消费者时间：</translation>
    </message>
    <message>
        <source>Node guarding, for a node without heartbeat: CoScope asks (RTR on %1h) every guard time</source>
        <translation>节点保护，用于没有心跳的节点：CoScope 每个节点守护时间询问一次（%1h 上的 RTR）</translation>
    </message>
    <message>
        <source>Guard time (100Ch):</source>
        <translation>节点守护时间（100Ch）：</translation>
    </message>
    <message>
        <source>Life time factor (100Dh):</source>
        <translation>寿命因子（100Dh）：</translation>
    </message>
    <message>
        <source>Lost after:</source>
        <translation>丢失判定：</translation>
    </message>
    <message>
        <source>Node %1 sends a heartbeat. CiA 301 guards only nodes without one (1017h = 0): while it sends both, its heartbeats can be taken for guarding answers.</source>
        <translation>节点 %1 会发送心跳。CiA 301 只对没有心跳的节点（1017h = 0）做节点保护：两者同时存在时，其心跳可能被当作保护应答。</translation>
    </message>
    <message>
        <source>%L1 ms without an answer</source>
        <translation>%L1 ms 无应答</translation>
    </message>
</context>
<context>
    <name>coscope::gui::EventsDock</name>
    <message>
        <source>Events</source>
        <translation>事件</translation>
    </message>
    <message>
        <source>Double-click an event to show its frame in the trace; click a column&apos;s title to sort</source>
        <translation>双击事件可在跟踪中显示其帧；点击列标题可排序</translation>
    </message>
    <message>
        <source>Only the events of one node</source>
        <translation>只显示单一节点的事件</translation>
    </message>
    <message>
        <source>All nodes</source>
        <translation>所有节点</translation>
    </message>
    <message>
        <source>Only the events of one kind</source>
        <translation>只显示单一类型的事件</translation>
    </message>
    <message>
        <source>All kinds</source>
        <translation>所有类型</translation>
    </message>
    <message>
        <source>Only the events at least this severe</source>
        <translation>只显示至少达到此严重程度的事件</translation>
    </message>
    <message>
        <source>All severities</source>
        <translation>所有严重程度</translation>
    </message>
    <message>
        <source>Warnings and errors</source>
        <translation>警告和错误</translation>
    </message>
    <message>
        <source>Errors only</source>
        <translation>仅错误</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>导出 CSV…</translation>
    </message>
    <message>
        <source>Write the events shown (with the filters and the order above) to a CSV file</source>
        <translation>将当前显示的事件（按上方的筛选和排序）写入 CSV 文件</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>%L1 of %L2 events</source>
        <translation>%L2 个事件中的 %L1 个</translation>
    </message>
    <message numerus="yes">
        <source>%Ln event(s)</source>
        <translation>
            <numerusform>%Ln 个事件</numerusform>
        </translation>
    </message>
    <message>
        <source>Export events</source>
        <translation>导出事件</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>The events could not be written: %1</source>
        <translation>无法写入事件：%1</translation>
    </message>
    <message numerus="yes">
        <source>%Ln event(s) written to %1</source>
        <translation>
            <numerusform>已将 %Ln 个事件写入 %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>coscope::gui::EventsModel</name>
    <message>
        <source>Time (s)</source>
        <translation>时间（秒）</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>节点</translation>
    </message>
    <message>
        <source>Event</source>
        <translation>事件</translation>
    </message>
    <message>
        <source>Details</source>
        <translation>详细信息</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation>帧</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>严重程度</translation>
    </message>
</context>
<context>
    <name>coscope::gui::FrameDetailsView</name>
    <message>
        <source>Field</source>
        <translation>字段</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>Bytes</source>
        <translation>字节</translation>
    </message>
    <message>
        <source>SDO transfer</source>
        <translation>SDO 传输</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>节点</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>对象</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>upload (read from the server)</source>
        <translation>上传（从 SDO 服务器读取）</translation>
    </message>
    <message>
        <source>download (write to the server)</source>
        <translation>下载（写入 SDO 服务器）</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>模式</translation>
    </message>
    <message>
        <source>block</source>
        <translation>块</translation>
    </message>
    <message>
        <source>segmented</source>
        <translation>分段</translation>
    </message>
    <message>
        <source>expedited</source>
        <translation>加速</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>大小</translation>
    </message>
    <message numerus="yes">
        <source>%n byte(s)</source>
        <translation>
            <numerusform>%n 字节</numerusform>
        </translation>
    </message>
    <message>
        <source>Data</source>
        <translation>数据</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Abort code</source>
        <translation>中止码</translation>
    </message>
    <message>
        <source>Abort reason</source>
        <translation>中止原因</translation>
    </message>
    <message>
        <source>Frames</source>
        <translation>帧</translation>
    </message>
    <message>
        <source>1 (frame %1)</source>
        <translation>1（帧 %1）</translation>
    </message>
    <message>
        <source>%1 (frames %2–%3)</source>
        <translation>%1（帧 %2–%3）</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>持续时间</translation>
    </message>
    <message>
        <source>Frame %1</source>
        <translation>帧 %1</translation>
    </message>
    <message>
        <source>Identifier</source>
        <translation>标识符</translation>
    </message>
    <message>
        <source>Service</source>
        <translation>服务</translation>
    </message>
    <message>
        <source>, node %1</source>
        <translation>，节点 %1</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>长度</translation>
    </message>
    <message>
        <source> (remote request)</source>
        <translation> （远程请求）</translation>
    </message>
    <message>
        <source>transmitted</source>
        <translation>已发送</translation>
    </message>
    <message>
        <source>error frame</source>
        <translation>错误帧</translation>
    </message>
    <message>
        <source>Flags</source>
        <translation>标志</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>byte %1</source>
        <translation>字节 %1</translation>
    </message>
    <message>
        <source>bytes %1–%2</source>
        <translation>字节 %1–%2</translation>
    </message>
    <message>
        <source>, bit %1</source>
        <translation>，位 %1</translation>
    </message>
    <message>
        <source>, bits %1–%2</source>
        <translation>，位 %1–%2</translation>
    </message>
    <message>
        <source>(no payload)</source>
        <translation>（无数据内容）</translation>
    </message>
    <message>
        <source>%1h (%2-bit)</source>
        <translation>%1h（%2 位）</translation>
    </message>
    <message>
        <source>Loading the frame back from the capture journal…</source>
        <extracomment>Details pane while the selected frame is read back from the capture journal on disk</extracomment>
        <translation>正在从捕获日志读回帧…</translation>
    </message>
</context>
<context>
    <name>coscope::gui::HealthDock</name>
    <message>
        <source>Health</source>
        <translation>健康状态</translation>
    </message>
    <message>
        <source>No frames yet</source>
        <translation>尚无帧</translation>
    </message>
    <message>
        <source>What to look at first, the worst at the top</source>
        <translation>应优先查看的项目，最严重的在最上方</translation>
    </message>
    <message>
        <source>Nodes</source>
        <translation>节点</translation>
    </message>
    <message>
        <source>PDOs</source>
        <translation>PDO</translation>
    </message>
    <message>
        <source>Average load</source>
        <translation>平均负载</translation>
    </message>
    <message>
        <source>Peak load</source>
        <translation>峰值负载</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>时间（秒）</translation>
    </message>
    <message>
        <source>Bus load (%)</source>
        <translation>总线负载（%）</translation>
    </message>
    <message>
        <source>Bus load</source>
        <translation>总线负载</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s) over %1 s; bus load average %2 %, peak %3 % at %4 bit/s; %5 error frame(s)</source>
        <translation>
            <numerusform>%1 秒内共 %n 帧；总线负载平均 %2 %，峰值 %3 %，波特率 %4 bit/s；%5 个错误帧</numerusform>
        </translation>
    </message>
    <message>
        <source>Click a finding to see what happened, why it matters and what to check, and its first frame in the trace.</source>
        <translation>点击发现项，查看发生了什么、为何重要、该检查什么，并在跟踪中显示其第一帧。</translation>
    </message>
    <message>
        <source>Previous occurrence</source>
        <translation>上一次出现</translation>
    </message>
    <message>
        <source>Show the finding&apos;s previous frame in the trace (Shift+F8)</source>
        <translation>在跟踪中显示此发现项的上一帧（Shift+F8）</translation>
    </message>
    <message>
        <source>Next occurrence</source>
        <translation>下一次出现</translation>
    </message>
    <message>
        <source>Show the finding&apos;s next frame in the trace (F8)</source>
        <translation>在跟踪中显示此发现项的下一帧（F8）</translation>
    </message>
    <message>
        <source>%1 critical</source>
        <translation>%1 个严重</translation>
    </message>
    <message>
        <source>1 error</source>
        <translation>1 个错误</translation>
    </message>
    <message>
        <source>%1 errors</source>
        <translation>%1 个错误</translation>
    </message>
    <message>
        <source>1 warning</source>
        <translation>1 个警告</translation>
    </message>
    <message>
        <source>%1 warnings</source>
        <translation>%1 个警告</translation>
    </message>
    <message>
        <source>No problems found</source>
        <translation>未发现问题</translation>
    </message>
    <message>
        <source>Problems found: %1</source>
        <translation>发现问题：%1</translation>
    </message>
    <message>
        <source>, </source>
        <translation>、</translation>
    </message>
    <message>
        <source>Once, at %1.</source>
        <translation>发生一次，于 %1。</translation>
    </message>
    <message>
        <source>%1 times, from %2 to %3.</source>
        <translation>共 %1 次，从 %2 到 %3。</translation>
    </message>
    <message>
        <source>Frame %1 of %2 shown in the trace.</source>
        <translation>跟踪中显示第 %1 帧（共 %2 帧）。</translation>
    </message>
    <message>
        <source>Click the finding to show its first frame in the trace.</source>
        <translation>点击此发现项，即可在跟踪中显示其第一帧。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Why:&lt;/b&gt;</source>
        <translation>&lt;b&gt;为何重要：&lt;/b&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Check:&lt;/b&gt;</source>
        <translation>&lt;b&gt;检查：&lt;/b&gt;</translation>
    </message>
    <message>
        <source>CoScope&apos;s own traffic: not counted in the verdict.</source>
        <translation>CoScope 自己的通信：不计入结论。</translation>
    </message>
    <message>
        <source>Export report…</source>
        <translation>导出报告…</translation>
    </message>
    <message>
        <source>Save the report for a ticket: an HTML page or a PDF, each finding with the frame numbers it rests on</source>
        <translation>将报告保存为可附在工单中的文件：HTML 网页或 PDF，每个发现项都附上其依据的帧编号</translation>
    </message>
    <message>
        <source>HTML page (*.html)</source>
        <translation>HTML 网页 (*.html)</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Export the health report</source>
        <translation>导出健康报告</translation>
    </message>
    <message>
        <source>The report could not be written: %1</source>
        <translation>无法写入报告：%1</translation>
    </message>
    <message>
        <source>Health report written to %1</source>
        <translation>健康报告已写入 %1</translation>
    </message>
</context>
<context>
    <name>coscope::gui::HealthModel</name>
    <message>
        <source>Severity</source>
        <translation>严重程度</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>节点</translation>
    </message>
    <message>
        <source>Finding</source>
        <translation>发现项目</translation>
    </message>
    <message>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Error control</source>
        <translation>错误控制</translation>
    </message>
    <message>
        <source>Beats</source>
        <translation>心跳次数</translation>
    </message>
    <message>
        <source>Period min/avg/max ms</source>
        <translation>周期 最小/平均/最大 ms</translation>
    </message>
    <message>
        <source>Late</source>
        <translation>延迟</translation>
    </message>
    <message>
        <source>Timeouts</source>
        <translation>超时</translation>
    </message>
    <message>
        <source>Boot-ups</source>
        <translation>启动报文</translation>
    </message>
    <message>
        <source>Resets</source>
        <translation>复位次数</translation>
    </message>
    <message>
        <source>SDO transfers</source>
        <translation>SDO 传输</translation>
    </message>
    <message>
        <source>SDO p99 ms</source>
        <translation>SDO 响应 p99（ms）</translation>
    </message>
    <message>
        <source>SDO aborts</source>
        <translation>SDO 中止</translation>
    </message>
    <message>
        <source>SDO timeouts</source>
        <translation>SDO 超时</translation>
    </message>
    <message>
        <source>EMCY</source>
        <translation>EMCY</translation>
    </message>
    <message>
        <source>COB-ID</source>
        <translation>COB-ID</translation>
    </message>
    <message>
        <source>PDO</source>
        <translation>PDO</translation>
    </message>
    <message>
        <source>Frames</source>
        <translation>帧</translation>
    </message>
    <message>
        <source>Rate Hz</source>
        <translation>频率 Hz</translation>
    </message>
    <message>
        <source>Jitter ms</source>
        <translation>抖动 ms</translation>
    </message>
    <message>
        <source>Critical</source>
        <translation>严重</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>错误</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>Info</source>
        <translation>信息</translation>
    </message>
    <message>
        <source>bus</source>
        <translation>总线</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>guarding stopped</source>
        <translation>节点保护已停止</translation>
    </message>
    <message>
        <source>heartbeat stopped</source>
        <translation>心跳已停止</translation>
    </message>
    <message>
        <source>guarding</source>
        <translation>节点保护</translation>
    </message>
    <message>
        <source>heartbeat</source>
        <translation>心跳</translation>
    </message>
    <message>
        <source>%1 (no consumer)</source>
        <translation>%1（无消费者）</translation>
    </message>
    <message>
        <source>event-driven</source>
        <translation>事件驱动</translation>
    </message>
    <message>
        <source>Why:</source>
        <translation>为何重要：</translation>
    </message>
    <message>
        <source>Check:</source>
        <translation>检查：</translation>
    </message>
</context>
<context>
    <name>coscope::gui::HeartbeatGuardQuestion</name>
    <message>
        <source>Stop the drive if CoScope dies?</source>
        <translation>CoScope 崩溃时让驱动器停止？</translation>
    </message>
    <message>
        <source>Node %1 is enabled by CoScope. Should it stop by itself if CoScope or the cable dies?</source>
        <translation>节点 %1 已由 CoScope 使能。若 CoScope 崩溃或线缆断开，是否让它自行停止？</translation>
    </message>
    <message>
        <source>CoScope will produce its heartbeat (node %1) every %2 ms and set node %3&apos;s heartbeat consumer 1016h and its abort connection option 6007h (quick stop, where the drive has one), so the drive stops by itself within %4 ms when CoScope or the cable dies. The old values are put back when the drive is disabled or the bus closes.</source>
        <translation>CoScope 将每 %2 ms 发送自己的心跳（节点 %1），并设置节点 %3 的消费者心跳时间 1016h 与中止连接选项 6007h（快速停止，若驱动器有此对象），使 CoScope 崩溃或线缆断开时驱动器在 %4 ms 内自行停止。驱动器去使能或总线关闭时会写回原值。</translation>
    </message>
    <message>
        <source>Guard the drive</source>
        <translation>保护驱动器</translation>
    </message>
    <message>
        <source>Not now</source>
        <translation>暂不</translation>
    </message>
    <message>
        <source>Remember my answer</source>
        <translation>记住我的选择</translation>
    </message>
    <message>
        <source>Node %1 does not watch CoScope&apos;s heartbeat: if CoScope or the cable dies, it keeps its last command</source>
        <translation>节点 %1 不监视 CoScope 的心跳：若 CoScope 崩溃或线缆断开，它会保持最后的命令</translation>
    </message>
    <message>
        <source>Heartbeat guard: %1</source>
        <translation>心跳保护：%1</translation>
    </message>
</context>
<context>
    <name>coscope::gui::IntegerSpinBox</name>
    <message>
        <source>Type a number: decimal (31), or hex as 0x1F or 1Fh</source>
        <translation>请输入数字：十进制 (31)，或十六进制 0x1F 或 1Fh</translation>
    </message>
    <message>
        <source>“%1” is not a number: type it in decimal (31, -5), or in hex as 0x1F or 1Fh</source>
        <translation>“%1”不是数字：请以十进制 (31, -5) 或十六进制 0x1F 或 1Fh 输入</translation>
    </message>
    <message>
        <source>“%1” is not a number: type it in decimal (31), or in hex as 0x1F or 1Fh</source>
        <translation>“%1”不是数字：请以十进制 (31) 或十六进制 0x1F 或 1Fh 输入</translation>
    </message>
    <message>
        <source>%1 is out of range: %2 … %3</source>
        <translation>%1 超出范围：%2 … %3</translation>
    </message>
</context>
<context>
    <name>coscope::gui::JournalOfferBar</name>
    <message>
        <source>Unclosed capture</source>
        <translation>未关闭的捕获</translation>
    </message>
    <message>
        <source>Reopen capture</source>
        <translation>重新打开捕获</translation>
    </message>
    <message>
        <source>Dismiss</source>
        <translation>忽略</translation>
    </message>
    <message>
        <source>A capture was not closed: CoScope ended without closing it (killed, crashed or the power went out). Its journal %1 (%2, last written %3) holds everything received up to about a second before.</source>
        <translation>有一个捕获未关闭：CoScope 结束时没有关闭它（被强制终止、崩溃或断电）。其日志 %1（%2，最后写入于 %3）保存了大约一秒前为止收到的所有内容。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::MainWindow</name>
    <message>
        <source>Capture stopped</source>
        <translation>捕获已停止</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Open log…</source>
        <translation>打开日志文件(&amp;O)…</translation>
    </message>
    <message>
        <source>Open CAN log</source>
        <translation>打开 CAN 日志文件</translation>
    </message>
    <message>
        <source>&amp;Save trace as…</source>
        <translation>另存跟踪(&amp;S)…</translation>
    </message>
    <message>
        <source>Save trace</source>
        <translation>保存跟踪</translation>
    </message>
    <message>
        <source>&amp;Export filtered rows…</source>
        <translation>导出筛选后的行(&amp;E)…</translation>
    </message>
    <message>
        <source>Export filtered rows</source>
        <translation>导出筛选后的行</translation>
    </message>
    <message>
        <source>Export PDO layout as &amp;DBC…</source>
        <translation>将 PDO 配置导出为 &amp;DBC…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;Bus</source>
        <translation>总线(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Connect…</source>
        <translation>连接(&amp;C)…</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>Connect to &amp;virtual drives (sim://)</source>
        <translation>连接到虚拟驱动器（sim://）(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Recent connections</source>
        <translation>最近的连接(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>中断连接(&amp;D)</translation>
    </message>
    <message>
        <source>Bus</source>
        <translation>总线</translation>
    </message>
    <message>
        <source>&amp;Commission</source>
        <translation>调试(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>查看(&amp;V)</translation>
    </message>
    <message>
        <source>Reset layout</source>
        <translation>重设布局</translation>
    </message>
    <message>
        <source>The default layout applies at the next start</source>
        <translation>默认布局会在下次启动时应用</translation>
    </message>
    <message>
        <source>Reopened the capture journal %1</source>
        <translation>已重新打开捕获日志 %1</translation>
    </message>
    <message>
        <source>Cannot connect to %1: %2</source>
        <translation>无法连接到 %1：%2</translation>
    </message>
    <message>
        <source>A save is already running</source>
        <translation>已有一个保存作业在运行</translation>
    </message>
    <message>
        <source>Connect to a bus first</source>
        <translation>请先连接到总线</translation>
    </message>
    <message>
        <source>Listen-only bus: commissioning would transmit</source>
        <translation>仅监听总线：调试需要发送</translation>
    </message>
    <message>
        <source>Listen-only bus</source>
        <translation>仅监听总线</translation>
    </message>
    <message>
        <source>A save is still running; wait for it or cancel it first</source>
        <translation>仍有保存作业在运行；请等它完成或先取消</translation>
    </message>
    <message>
        <source>Unsaved capture</source>
        <translation>未保存的捕获</translation>
    </message>
    <message>
        <source>The trace holds %L1 frames that are not saved. Save the capture first?</source>
        <translation>跟踪中有 %L1 帧尚未保存。要先保存捕获内容吗？</translation>
    </message>
    <message>
        <source>%1: %L2 frames, %L3 lines not understood — first: %4</source>
        <translation>%1：%L2 帧，%L3 行无法解析——第一行：%4</translation>
    </message>
    <message>
        <source>%1: %L2 frames (%3)</source>
        <translation>%1：%L2 帧（%3）</translation>
    </message>
    <message>
        <source>Save cancelled</source>
        <translation>已取消保存</translation>
    </message>
    <message>
        <source>Saved %L1 frames to %2</source>
        <translation>已将 %L1 帧保存至 %2</translation>
    </message>
    <message>
        <source>Could not read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>%1 read as %2: %L3 lines, %L4 frames, %L5 lines skipped.</source>
        <translation>%1 以 %2 格式读取：%L3 行，%L4 帧，跳过 %L5 行。</translation>
    </message>
    <message>
        <source>%1 read as %2: %L3 frames, %L4 records skipped.</source>
        <translation>%1 以 %2 格式读取：%L3 帧，跳过 %L4 条记录。</translation>
    </message>
    <message>
        <source>No frames were found in this file.</source>
        <translation>此文件中找不到任何帧。</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation>第 %1 行：%2</translation>
    </message>
    <message>
        <source>… and %L1 more</source>
        <translation>… 另有 %L1 项</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <source>System language (%1)</source>
        <extracomment>View ▸ Language: follow the operating system&apos;s language; %1 = that language&apos;s own name</extracomment>
        <translation>系统语言（%1）</translation>
    </message>
    <message>
        <source>Close the other windows (wizards, dialogs) to change the language</source>
        <translation>请先关闭其他窗口（向导、对话框）再切换语言</translation>
    </message>
    <message>
        <source>Capture se&amp;ttings…</source>
        <translation>捕获设置(&amp;T)…</translation>
    </message>
    <message numerus="yes">
        <source>Removed %n old capture journal(s)</source>
        <translation>
            <numerusform>已删除 %n 个旧的捕获日志</numerusform>
        </translation>
    </message>
    <message>
        <source>An export is already running</source>
        <translation>已有一项导出正在进行</translation>
    </message>
    <message>
        <source>Recent &amp;logs</source>
        <translation>最近的日志文件(&amp;L)</translation>
    </message>
</context>
<context>
    <name>coscope::gui::MasterActions</name>
    <message>
        <source>&amp;SYNC producer</source>
        <translation>SYNC 生产者(&amp;S)</translation>
    </message>
    <message>
        <source>SYNC</source>
        <translation>SYNC</translation>
    </message>
    <message>
        <source>SYNC stopped</source>
        <translation>SYNC 已停止</translation>
    </message>
    <message>
        <source>Cannot start SYNC: %1</source>
        <translation>无法启动 SYNC：%1</translation>
    </message>
    <message>
        <source>&amp;Master settings…</source>
        <translation>主站设置(&amp;M)…</translation>
    </message>
    <message>
        <source>the bus is listen-only</source>
        <translation>总线为仅监听</translation>
    </message>
    <message>
        <source>no bus is open</source>
        <translation>没有已打开的总线</translation>
    </message>
    <message>
        <source>SYNC every %1 on %2h</source>
        <translation>SYNC 每 %1 一次，COB-ID %2h</translation>
    </message>
    <message>
        <source>node %1 (%2)</source>
        <translation>节点 %1（%2）</translation>
    </message>
    <message numerus="yes">
        <source>1006h = %1 µs written to %n node(s)</source>
        <translation>
            <numerusform>已将 1006h = %1 µs 写入 %n 个节点</numerusform>
        </translation>
    </message>
    <message>
        <source>1006h not written to %1</source>
        <translation>1006h 未写入：%1</translation>
    </message>
    <message>
        <source>Cannot start CoScope&apos;s heartbeat: %1</source>
        <translation>无法启动 CoScope 的心跳：%1</translation>
    </message>
    <message>
        <source>Connect to a bus first</source>
        <translation>请先连接到总线</translation>
    </message>
    <message>
        <source>Listen-only connection: CoScope sends nothing</source>
        <translation>仅监听连接：CoScope 不发送任何帧</translation>
    </message>
    <message>
        <source>The bus is not open</source>
        <translation>总线未打开</translation>
    </message>
    <message>
        <source>Start or stop the SYNC producer (Bus ▸ Master settings… sets its period)</source>
        <translation>启动或停止 SYNC 生产者（周期在“总线 ▸ 主站设置…”中设置）</translation>
    </message>
    <message>
        <source>SYNC stopped: %1</source>
        <translation>SYNC 已停止：%1</translation>
    </message>
    <message>
        <source>SYNC %1 (%L2)</source>
        <translation>SYNC %1（%L2）</translation>
    </message>
    <message>
        <source>CoScope&apos;s heartbeat keeps running as it is while a drive watches it; the new settings apply once it is released</source>
        <translation>有驱动器监视 CoScope 的心跳时，心跳保持原样；新设置在释放后才生效</translation>
    </message>
    <message>
        <source>Heartbeat %1 ms</source>
        <translation>心跳 %1 ms</translation>
    </message>
    <message numerus="yes">
        <source>guarding node %1</source>
        <translation>
            <numerusform>保护节点 %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>coscope::gui::MasterSettings</name>
    <message>
        <source>%1 µs</source>
        <translation>%1 µs</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
</context>
<context>
    <name>coscope::gui::MasterSettingsDialog</name>
    <message>
        <source>Master settings</source>
        <translation>主站设置</translation>
    </message>
    <message>
        <source>SYNC producer</source>
        <translation>SYNC 生产者</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Communication cycle period (1006h): the time between two SYNC messages, to the microsecond</source>
        <translation>通信循环周期（1006h）：两个 SYNC 报文之间的时间，精确到微秒</translation>
    </message>
    <message>
        <source>Period:</source>
        <translation>周期：</translation>
    </message>
    <message>
        <source>No counter</source>
        <translation>无计数器</translation>
    </message>
    <message>
        <source>Synchronous counter overflow value (1019h): 0 = SYNC without data; 2-240 = SYNC carries a counter 1…N</source>
        <translation>同步计数器溢出值（1019h）：0 = SYNC 不带数据；2-240 = SYNC 带计数器 1…N</translation>
    </message>
    <message>
        <source>Counter overflow (1019h):</source>
        <translation>计数器溢出值（1019h）：</translation>
    </message>
    <message>
        <source>COB-ID of the SYNC message (1005h), 80h by default; hex as 80h or 0x80</source>
        <translation>SYNC 报文的 COB-ID（1005h），默认 80h；十六进制写成 80h 或 0x80</translation>
    </message>
    <message>
        <source>COB-ID (1005h):</source>
        <translation>COB-ID（1005h）：</translation>
    </message>
    <message>
        <source>Write the period to the nodes&apos; 1006h when SYNC starts</source>
        <translation>SYNC 启动时将周期写入各节点的 1006h</translation>
    </message>
    <message>
        <source>CoScope&apos;s heartbeat</source>
        <translation>CoScope 的心跳</translation>
    </message>
    <message>
        <source>CoScope sends a heartbeat (700h + node-ID, state Operational) so that drives whose heartbeat consumer (1016h) watches it stop by themselves when CoScope or the cable goes away</source>
        <translation>CoScope 发送心跳（700h + 节点 ID，状态为操作状态），让以心跳消费者（1016h）监视它的驱动器在 CoScope 或电缆断开时自行停止</translation>
    </message>
    <message>
        <source>Node-ID:</source>
        <translation>节点 ID：</translation>
    </message>
    <message>
        <source>The counter overflow must be 0 (no counter) or 2-240 (CiA 301, 1019h).</source>
        <translation>计数器溢出值必须为 0（无计数器）或 2-240（CiA 301，1019h）。</translation>
    </message>
    <message>
        <source>The COB-ID “%1” is not a number (write 80h, 0x80 or 128).</source>
        <translation>COB-ID“%1”不是数字（请写 80h、0x80 或 128）。</translation>
    </message>
    <message>
        <source>The COB-ID %1h is not an 11-bit CAN-ID (set bit 29 for a 29-bit one).</source>
        <translation>COB-ID %1h 不是 11 位 CAN-ID（29 位的请设置位 29）。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodeIdChangePage</name>
    <message>
        <source>What to change</source>
        <translation>要更改的项目</translation>
    </message>
    <message>
        <source>The node-ID (the device&apos;s address on the bus, 1-127) or the baud rate (CAN bit rate).</source>
        <translation>节点 ID（设备在总线上的地址，1-127）或波特率（CAN 比特率）。</translation>
    </message>
    <message>
        <source>Node-ID</source>
        <translation>节点 ID</translation>
    </message>
    <message>
        <source>Baud rate (bit rate)</source>
        <translation>波特率（比特率）</translation>
    </message>
    <message>
        <source>LSS (layer setting services, CiA 305) — works for any LSS-capable device</source>
        <translation>LSS（层设置服务，CiA 305）——适用于任何支持 LSS 的设备</translation>
    </message>
    <message>
        <source>Change:</source>
        <translation>更改：</translation>
    </message>
    <message>
        <source>New node-ID:</source>
        <translation>新节点 ID：</translation>
    </message>
    <message>
        <source>New baud rate:</source>
        <translation>新波特率：</translation>
    </message>
    <message>
        <source>How:</source>
        <translation>方式：</translation>
    </message>
    <message>
        <source>The drive&apos;s own parameter %1 over SDO — as its manual describes</source>
        <translation>通过 SDO 写入驱动器自己的参数 %1——按其手册所述</translation>
    </message>
    <message>
        <source>The drive&apos;s own parameter — none documented for this device</source>
        <translation>驱动器自己的参数——此设备没有相关文档</translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodeIdFindPage</name>
    <message>
        <source>Find the device</source>
        <translation>找出设备</translation>
    </message>
    <message>
        <source>Pick the drive whose node-ID or baud rate (bit rate) you want to change.</source>
        <translation>选择要更改节点 ID 或波特率（比特率）的驱动器。</translation>
    </message>
    <message>
        <source>These are the devices CoScope has seen on the bus. &lt;b&gt;Scan&lt;/b&gt; asks every node-ID 1-127 for its device type and identity (SDO reads, changes nothing). A new device without node-ID (LSS-unconfigured) stays silent: &lt;b&gt;Find device without node-ID&lt;/b&gt; finds it with LSS Fastscan (CiA 305).</source>
        <translation>以下是 CoScope 在总线上看到的设备。&lt;b&gt;扫描&lt;/b&gt;会向节点 ID 1-127 逐一查找设备类型与识别信息（SDO 读取，不更改任何内容）。没有节点 ID 的新设备（尚未 LSS 设置）不会发出任何消息：&lt;b&gt;查找没有节点 ID 的设备&lt;/b&gt;会以 LSS Fastscan（CiA 305）找出它。</translation>
    </message>
    <message>
        <source>Node-ID</source>
        <translation>节点 ID</translation>
    </message>
    <message>
        <source>Device (dictionary)</source>
        <translation>设备（字典）</translation>
    </message>
    <message>
        <source>State (NMT)</source>
        <translation>状态（NMT）</translation>
    </message>
    <message>
        <source>Scan the bus</source>
        <translation>扫描总线</translation>
    </message>
    <message>
        <source>Find device without node-ID (LSS Fastscan)</source>
        <translation>查找没有节点 ID 的设备（LSS Fastscan）</translation>
    </message>
    <message>
        <source>Scanning node-IDs 1-127…</source>
        <translation>正在扫描节点 ID 1-127…</translation>
    </message>
    <message>
        <source>LSS Fastscan: looking for a device without node-ID…</source>
        <translation>LSS Fastscan：正在查找没有节点 ID 的设备…</translation>
    </message>
    <message numerus="yes">
        <source>Scan finished: %n device(s) known.</source>
        <translation>
            <numerusform>扫描完成：已知 %n 台设备。</numerusform>
        </translation>
    </message>
    <message>
        <source>(unknown — LSS only)</source>
        <translation>（未知——仅 LSS）</translation>
    </message>
    <message>
        <source>Device type:</source>
        <translation>设备类型：</translation>
    </message>
    <message>
        <source>(not identified — scan)</source>
        <translation>（未识别——请扫描）</translation>
    </message>
    <message>
        <source>Target: the device without node-ID found by LSS Fastscan.</source>
        <translation>目标：以 LSS Fastscan 找到的无节点 ID 设备。</translation>
    </message>
    <message>
        <source>Target: node %1%2.</source>
        <translation>目标：节点 %1%2。</translation>
    </message>
    <message>
        <source>No device chosen yet.</source>
        <translation>尚未选择设备。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodeIdRunPage</name>
    <message>
        <source>Dry run: nothing has been sent yet. This is exactly what CoScope will send, and why.</source>
        <translation>模拟运行：尚未发送任何内容。以下正是 CoScope 将要发送的内容与原因。</translation>
    </message>
    <message>
        <source>Check and change</source>
        <translation>检查并更改</translation>
    </message>
    <message>
        <source>Change it now</source>
        <translation>立即更改</translation>
    </message>
    <message>
        <source>Sending: CoScope runs the sequence below; each step turns green when the device has answered.</source>
        <translation>发送中：CoScope 正在运行下列顺序；设备响应后该步骤会变成绿色。</translation>
    </message>
    <message>
        <source>Takes effect: %1</source>
        <translation>生效时机：%1</translation>
    </message>
    <message>
        <source>CoScope will reconnect at %1 after the first part.</source>
        <translation>第一部分完成后，CoScope 会以 %1 重新连接。</translation>
    </message>
    <message>
        <source>Cannot prepare the change: %1</source>
        <translation>无法准备更改：%1</translation>
    </message>
    <message>
        <source>Sent: the sequence below ran to the end. The device has its new setting.</source>
        <translation>已发送：下列顺序已全部运行完毕。设备已应用新设置。</translation>
    </message>
    <message>
        <source>Stopped: the green steps below were sent, the red one failed, the rest was not sent.</source>
        <translation>已停止：下列绿色步骤已发送，红色步骤失败，其余未发送。</translation>
    </message>
    <message>
        <source>Preparing the sequence…</source>
        <translation>正在准备顺序…</translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodeIdWizard</name>
    <message>
        <source>Baud rate and node-ID — CoScope</source>
        <translation>波特率与节点 ID — CoScope</translation>
    </message>
    <message>
        <source>Not connected to a bus: this wizard talks to the devices, so connect first (File ▸ Connect).</source>
        <translation>未连接到总线：此向导需要与设备通信，请先连接（文件 ▸ 连接）。</translation>
    </message>
    <message>
        <source>The bus is open listen-only: CoScope never transmits on it, so this wizard cannot change anything. Reconnect without listen-only to use it.</source>
        <translation>总线以仅监听方式打开：CoScope 不会在上面发送，因此此向导无法更改任何设置。请取消仅监听后重新连接再使用。</translation>
    </message>
    <message>
        <source>The bus is not open (yet): wait for it to connect.</source>
        <translation>总线（尚）未打开：请等待连接完成。</translation>
    </message>
    <message>
        <source>The connection was closed while the change was running. Connect again and scan to see where the device is.</source>
        <translation>更改进行中连接被关闭。请重新连接并扫描，确认设备当前的位置。</translation>
    </message>
    <message>
        <source>No device without node-ID answered (LSS Fastscan). Every device on the bus has a node-ID.</source>
        <translation>没有无节点 ID 的设备响应（LSS Fastscan）。总线上每台设备都有节点 ID。</translation>
    </message>
    <message>
        <source>Found a device without node-ID: vendor %1h, product %2h, serial %3h. It waits in LSS configuration state for its node-ID.</source>
        <translation>找到一台没有节点 ID 的设备：厂商 %1h，产品 %2h，序列号 %3h。它正在 LSS 设置状态中等待节点 ID。</translation>
    </message>
    <message>
        <source>Choose a device first.</source>
        <translation>请先选择设备。</translation>
    </message>
    <message>
        <source>Choose the new node-ID.</source>
        <translation>请选择新的节点 ID。</translation>
    </message>
    <message>
        <source>The device already has node-ID %1.</source>
        <translation>设备的节点 ID 已经是 %1。</translation>
    </message>
    <message>
        <source>Node-ID %1 is already used by another device on this bus: two devices with one node-ID break communication.</source>
        <translation>节点 ID %1 已被此总线上的另一台设备使用：两台设备使用同一个节点 ID 会导致通信中断。</translation>
    </message>
    <message>
        <source>Choose a bit rate other than the one the bus runs at now (%1).</source>
        <translation>请选择与总线当前波特率（%1）不同的比特率。</translation>
    </message>
    <message>
        <source>the device without node-ID</source>
        <translation>无节点 ID 的设备</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;How:&lt;/b&gt; LSS (layer setting services, CiA 305) picks %1 by its identity (1018h) and gives it the new setting; the device stores it itself.</source>
        <translation>&lt;b&gt;方式：&lt;/b&gt;LSS（层设置服务，CiA 305）按识别信息（1018h）选中 %1 并给予新设置；设备会自行保存。</translation>
    </message>
    <message>
        <source>&lt;b&gt;How:&lt;/b&gt; CoScope writes the drive&apos;s own parameter %1 over SDO (the way its manual describes).</source>
        <translation>&lt;b&gt;方式：&lt;/b&gt;CoScope 通过 SDO 写入驱动器自己的参数 %1（按其手册所述的方式）。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Takes effect:&lt;/b&gt; %1.</source>
        <translation>&lt;b&gt;生效时机：&lt;/b&gt;%1。</translation>
    </message>
    <message>
        <source>&lt;b&gt;About this drive:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;关于此驱动器：&lt;/b&gt;%1</translation>
    </message>
    <message>
        <source>&lt;b style=&apos;color:#a40000&apos;&gt;Every other node on this bus&lt;/b&gt; (%1) stays at %2. After the change, %3 only talks at %4: the others cannot reach it until they are changed too. Change them all, one after another, then the bus runs at %4.</source>
        <translation>&lt;b style=&apos;color:#a40000&apos;&gt;此总线上的其他所有节点&lt;/b&gt;（%1）仍维持 %2。更改后，%3 只会以 %4 通信：其他节点在更改之前都无法与它通信。请逐一更改所有节点，之后总线就会以 %4 运作。</translation>
    </message>
    <message>
        <source>none seen</source>
        <translation>未看到任何节点</translation>
    </message>
    <message>
        <source>nodes %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>CoScope reconnects at the new bit rate by itself and waits for %1 there.</source>
        <translation>CoScope 会自动以新的比特率重新连接，并在该速率下等待 %1。</translation>
    </message>
    <message>
        <source>&lt;b&gt;If it does not come back:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;如果它没有重新出现：&lt;/b&gt;%1</translation>
    </message>
    <message>
        <source>&lt;b style=&apos;color:#a40000&apos;&gt;Cannot do this:&lt;/b&gt; %1</source>
        <translation>&lt;b style=&apos;color:#a40000&apos;&gt;无法运行：&lt;/b&gt;%1</translation>
    </message>
    <message>
        <source>The change is already running.</source>
        <translation>更改已在进行中。</translation>
    </message>
    <message>
        <source>The sequence is not ready yet.</source>
        <translation>顺序尚未准备好。</translation>
    </message>
    <message>
        <source>Running…</source>
        <translation>运行中…</translation>
    </message>
    <message>
        <source>The connection is gone: %1</source>
        <translation>连接已中断：%1</translation>
    </message>
    <message>
        <source>Stopped at %1.
The device answered: %2
What to check: %3</source>
        <translation>停止于 %1。
设备响应：%2
检查事项：%3</translation>
    </message>
    <message>
        <source>Done: the device that was %1 now answers at node-ID %2 (it reported on the bus).</source>
        <translation>完成：原本为 %1 的设备现在以节点 ID %2 响应（已在总线上报告）。</translation>
    </message>
    <message>
        <source>without node-ID</source>
        <translation>无节点 ID</translation>
    </message>
    <message>
        <source>Done: node %1 now runs at %2 and CoScope is connected at %2. Nodes still at %3 cannot be reached at this rate: change them too, or reconnect at %3.</source>
        <translation>完成：节点 %1 现在以 %2 运作，CoScope 也已以 %2 连接。仍为 %3 的节点在此速率下无法通信：请一并更改，或以 %3 重新连接。</translation>
    </message>
    <message>
        <source>The connection is gone before reconnecting.</source>
        <translation>重新连接前连接已中断。</translation>
    </message>
    <message>
        <source>Reconnecting at %1 (%2)…</source>
        <translation>正在以 %1 重新连接（%2）…</translation>
    </message>
    <message>
        <source>Could not reconnect at %1: %2
%3</source>
        <translation>无法以 %1 重新连接：%2
%3</translation>
    </message>
    <message>
        <source>connected at %1</source>
        <translation>已以 %1 连接</translation>
    </message>
    <message>
        <source>The bus did not open at %1.
%2</source>
        <translation>总线无法以 %1 打开。
%2</translation>
    </message>
    <message>
        <source>Node %1 now answers at node-ID %2 (Baud rate and node-ID wizard)</source>
        <translation>节点 %1 现在以节点 ID %2 响应（波特率与节点 ID 向导）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodesDock</name>
    <message>
        <source>Nodes</source>
        <translation>节点</translation>
    </message>
    <message>
        <source>Scan network (SDO 1000h on nodes 1–127)</source>
        <translation>扫描网络（对节点 1–127 读取 SDO 1000h）</translation>
    </message>
    <message>
        <source>Scan network</source>
        <translation>扫描网络</translation>
    </message>
    <message>
        <source>Read identity</source>
        <translation>读取识别信息</translation>
    </message>
    <message>
        <source>Assign dictionary…</source>
        <translation>指定字典…</translation>
    </message>
    <message>
        <source>Assign dictionary</source>
        <translation>指定字典</translation>
    </message>
    <message>
        <source>Dictionary for node %1:</source>
        <translation>节点 %1 的字典：</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>All nodes</source>
        <translation>所有节点</translation>
    </message>
    <message>
        <source>Listen-only: commands disabled</source>
        <translation>仅监听：指令已停用</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>Scan finished: %1 node(s) answered</source>
        <translation>扫描完成：%1 个节点响应</translation>
    </message>
    <message>
        <source>A scan is running</source>
        <translation>扫描进行中</translation>
    </message>
    <message>
        <source>Listen-only bus: a scan would transmit</source>
        <translation>仅监听总线：扫描需要发送</translation>
    </message>
    <message>
        <source>Connect to a bus first</source>
        <translation>请先连接到总线</translation>
    </message>
    <message>
        <source>Read the device type 1000h of every node-ID 1–127, then each answering node&apos;s identity</source>
        <translation>读取节点 ID 1–127 每个节点的设备类型 1000h，再读取每个有响应节点的识别信息</translation>
    </message>
    <message>
        <source>Listen-only: NMT commands are disabled</source>
        <translation>仅监听：NMT 指令已停用</translation>
    </message>
    <message>
        <source>Not connected to a bus</source>
        <translation>未连接到总线</translation>
    </message>
    <message>
        <source>An NMT command is waiting for your answer</source>
        <translation>有一个 NMT 指令正在等待您的回复</translation>
    </message>
    <message>
        <source>all nodes</source>
        <translation>所有节点</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>Send NMT “%1” to %2?

Frame: %3</source>
        <translation>要将 NMT“%1”发送给 %2 吗？

帧：%3</translation>
    </message>
    <message>
        <source>Send NMT command</source>
        <translation>发送 NMT 指令</translation>
    </message>
    <message>
        <source>NMT %1 to %2 failed: %3</source>
        <translation>对 %2 发送 NMT %1 失败：%3</translation>
    </message>
    <message>
        <source>NMT command failed</source>
        <translation>NMT 指令失败</translation>
    </message>
    <message>
        <source>Sent NMT %1 to %2</source>
        <translation>已对 %2 发送 NMT %1</translation>
    </message>
    <message>
        <source>Drive %1 is enabled (Operation enabled, statusword 0x%2): %3 stops it abruptly; the motor loses torque or trips its communication-loss reaction (6007h). %4Disable it first (CiA 402 wizard: Disable).

</source>
        <translation>驱动器 %1 已使能（Operation enabled，状态字 0x%2）：%3会让它突然停止；电机会失去转矩或触发通信中断处理（6007h）。%4请先停用（CiA 402 向导：停用）。

</translation>
    </message>
    <message>
        <source>a reset</source>
        <translation>复位</translation>
    </message>
    <message>
        <source>this command</source>
        <translation>此指令</translation>
    </message>
    <message>
        <source>Delta drives raise AL401 (CANopen communication lost). </source>
        <translation>台达驱动器会发出 AL401（CANopen 通信中断）。</translation>
    </message>
    <message>
        <source>Scan needs a connected bus that is not listen-only</source>
        <translation>扫描需要已连接且非仅监听的总线</translation>
    </message>
    <message>
        <source>A scan is already running</source>
        <translation>已有扫描在进行中</translation>
    </message>
    <message>
        <source>Read object 1000h from every node-ID 1–127 (SDO upload requests on 601h–67Fh)?</source>
        <translation>要从节点 ID 1–127 逐一读取对象 1000h 吗（在 601h–67Fh 发送 SDO 上传请求）？</translation>
    </message>
    <message>
        <source>Scanning nodes 1–127…</source>
        <translation>正在扫描节点 1–127…</translation>
    </message>
    <message>
        <source>Node %1 uses dictionary %2</source>
        <translation>节点 %1 使用字典 %2</translation>
    </message>
    <message>
        <source>Heartbeat and guarding…</source>
        <translation>心跳与节点保护…</translation>
    </message>
    <message>
        <source>Listen-only bus: node guarding would transmit (an RTR each guard time); a heartbeat can still be watched.</source>
        <translation>只听总线：节点保护需要发送（每个节点守护时间一个 RTR）；仍可监视心跳。</translation>
    </message>
    <message>
        <source>The bus is not open: node guarding cannot send its requests.</source>
        <translation>总线未打开：节点保护无法发送请求。</translation>
    </message>
    <message>
        <source>Node guarding of node %1 not started: %2</source>
        <translation>节点 %1 的节点保护未启动：%2</translation>
    </message>
    <message>
        <source>Node guarding</source>
        <translation>节点保护</translation>
    </message>
    <message>
        <source>Node %1: node guarding every %2 ms, lost after %3 ms without an answer</source>
        <translation>节点 %1：每 %2 ms 节点保护一次，%3 ms 无应答即视为丢失</translation>
    </message>
    <message>
        <source>Node %1: heartbeat expected within %2 ms</source>
        <translation>节点 %1：预期 %2 ms 内收到心跳</translation>
    </message>
    <message>
        <source>Node %1 is no longer watched</source>
        <translation>节点 %1 不再监视</translation>
    </message>
    <message>
        <source>Download program…</source>
        <translation>下载程序…</translation>
    </message>
    <message>
        <source>Listen-only bus: a program download would transmit</source>
        <translation>仅监听总线：程序下载需要发送报文</translation>
    </message>
    <message>
        <source>Select a node first</source>
        <translation>请先选择节点</translation>
    </message>
    <message>
        <source>Load a new program (firmware) into the node: CiA 302-3 program download</source>
        <translation>将新程序（固件）载入节点：CiA 302-3 程序下载</translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodesModel</name>
    <message>
        <source>No heartbeat</source>
        <translation>无心跳</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>not present</source>
        <translation>不存在</translation>
    </message>
    <message>
        <source>Device name (1008h): %1
Hardware version (1009h): %2
Software version (100Ah): %3</source>
        <translation>设备名称（1008h）：%1
硬件版本（1009h）：%2
软件版本（100Ah）：%3</translation>
    </message>
    <message>
        <source>vendor %1</source>
        <translation>厂商 %1</translation>
    </message>
    <message>
        <source>, product %1</source>
        <translation>，产品 %1</translation>
    </message>
    <message>
        <source>, product not present</source>
        <translation>，无产品信息</translation>
    </message>
    <message>
        <source>, rev %1</source>
        <translation>，修订号 %1</translation>
    </message>
    <message>
        <source>, rev not present</source>
        <translation>，无修订号信息</translation>
    </message>
    <message>
        <source>, s/n %1</source>
        <translation>，序列号 %1</translation>
    </message>
    <message>
        <source>, s/n not present</source>
        <translation>，无序列号信息</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <source>boot-up</source>
        <translation>启动报文</translation>
    </message>
    <message>
        <source>heartbeat</source>
        <translation>心跳</translation>
    </message>
    <message>
        <source>scan</source>
        <translation>扫描</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>节点</translation>
    </message>
    <message>
        <source>NMT state</source>
        <translation>NMT 状态</translation>
    </message>
    <message>
        <source>Heartbeat age</source>
        <translation>心跳经过时间</translation>
    </message>
    <message>
        <source>Device name</source>
        <translation>设备名称</translation>
    </message>
    <message>
        <source>Identity (1018h)</source>
        <translation>识别信息（1018h）</translation>
    </message>
    <message>
        <source>Dictionary</source>
        <translation>字典</translation>
    </message>
    <message>
        <source>EMCY</source>
        <translation>EMCY</translation>
    </message>
    <message>
        <source>Seen by</source>
        <translation>检测来源</translation>
    </message>
    <message>
        <source>unknown (gap)</source>
        <translation>未知（中断）</translation>
    </message>
    <message>
        <source>node guarding</source>
        <translation>节点保护</translation>
    </message>
    <message>
        <source>after our NMT %1 (not confirmed)</source>
        <translation>在我们发送 NMT %1 之后（未确认）</translation>
    </message>
    <message>
        <source>after NMT %1 by another master (not confirmed)</source>
        <translation>在另一个主站发送 NMT %1 之后（未确认）</translation>
    </message>
    <message>
        <source>its PDOs</source>
        <translation>其 PDO</translation>
    </message>
    <message>
        <source>its SDO answers</source>
        <translation>其 SDO 应答</translation>
    </message>
    <message>
        <source>its EMCY</source>
        <translation>其紧急报文 (EMCY)</translation>
    </message>
    <message>
        <source>The node sent its boot-up message; after boot-up a node is Pre-operational.</source>
        <translation>节点发送了启动报文；启动后节点处于预操作状态。</translation>
    </message>
    <message>
        <source>The node&apos;s heartbeat says so.</source>
        <translation>由节点的心跳得知。</translation>
    </message>
    <message>
        <source>The node&apos;s answer to node guarding says so.</source>
        <translation>由节点对节点保护的应答得知。</translation>
    </message>
    <message>
        <source>CoScope sent NMT %1; the node has not confirmed it yet (no heartbeat, and no frame of its own that shows its state).</source>
        <translation>CoScope 发送了 NMT %1；节点尚未确认（没有心跳，也没有能显示其状态的自身帧）。</translation>
    </message>
    <message>
        <source>Another master sent NMT %1; the node has not confirmed it yet (no heartbeat, and no frame of its own that shows its state).</source>
        <translation>另一个主站发送了 NMT %1；节点尚未确认（没有心跳，也没有能显示其状态的自身帧）。</translation>
    </message>
    <message>
        <source>The node sends PDOs, which CiA 301 allows only in Operational.</source>
        <translation>节点正在发送 PDO，而 CiA 301 只允许在操作状态下发送。</translation>
    </message>
    <message>
        <source>The node answers SDO, which CiA 301 allows only in Pre-operational and Operational (its PDOs would show Operational).</source>
        <translation>节点应答 SDO，而 CiA 301 只允许在预操作状态和操作状态下应答（其 PDO 才能显示是否为操作状态）。</translation>
    </message>
    <message>
        <source>The node sends EMCY, which CiA 301 allows only in Pre-operational and Operational (its PDOs would show Operational).</source>
        <translation>节点发送紧急报文 (EMCY)，而 CiA 301 只允许在预操作状态和操作状态下发送（其 PDO 才能显示是否为操作状态）。</translation>
    </message>
    <message>
        <source>Nothing seen yet shows the node&apos;s state.</source>
        <translation>目前所见的内容尚无法显示节点的状态。</translation>
    </message>
    <message>
        <source>The bus was lost: the state is unknown until the node&apos;s heartbeat or its own frames show it (last known: %1)</source>
        <translation>总线中断：在节点的心跳或其自身帧显示状态之前，状态未知（最后已知：%1）</translation>
    </message>
    <message>
        <source>State from</source>
        <translation>状态来源</translation>
    </message>
    <message>
        <source>guarding %1 ms × %2</source>
        <translation>节点保护 %1 ms × %2</translation>
    </message>
    <message>
        <source>heartbeat %1 ms</source>
        <translation>心跳 %1 ms</translation>
    </message>
    <message>
        <source>waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>正常</translation>
    </message>
    <message>
        <source>late</source>
        <translation>延迟</translation>
    </message>
    <message>
        <source>lost</source>
        <translation>丢失</translation>
    </message>
    <message>
        <source>%1, %2 s ago</source>
        <translation>%1，%2 秒前</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>Not watched by CoScope (Heartbeat and guarding… in the context menu)</source>
        <translation>CoScope 未监视（右键菜单中的“心跳与节点保护…”）</translation>
    </message>
    <message>
        <source>Node guarding (CiA 301): CoScope asks every %1 ms; the node is late when a request goes unanswered or the toggle bit is wrong, lost after %2 ms without a right answer. Guarding errors: %3, lost %4 time(s).</source>
        <translation>节点保护（CiA 301）：CoScope 每 %1 ms 询问一次；请求无应答或翻转位错误时视为延迟，%2 ms 内无正确应答即视为丢失。保护错误：%3，丢失 %4 次。</translation>
    </message>
    <message>
        <source>Heartbeat consumer (CiA 301): late when a heartbeat is overdue, lost when none comes within %1 ms. Lost %2 time(s).</source>
        <translation>心跳消费者（CiA 301）：心跳超时视为延迟，%1 ms 内未收到即视为丢失。丢失 %2 次。</translation>
    </message>
    <message>
        <source>Heartbeat / guarding</source>
        <translation>心跳 / 节点保护</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ObjectDictionaryDock</name>
    <message>
        <source>Object Dictionary</source>
        <translation>对象字典</translation>
    </message>
    <message>
        <source>Search index or name (6060, 0x1018, heartbeat)</source>
        <translation>搜索索引或名称（6060、0x1018、heartbeat）</translation>
    </message>
    <message>
        <source>Only changed</source>
        <translation>仅显示已更改</translation>
    </message>
    <message>
        <source>Show only the values read from the node that differ from the dictionary&apos;s default</source>
        <translation>只显示从节点读取、且与字典默认值不同的值</translation>
    </message>
    <message>
        <source>Read all</source>
        <translation>全部读取</translation>
    </message>
    <message>
        <source>Read every readable object of the node over SDO (DOMAINs are skipped)</source>
        <translation>通过 SDO 读取节点所有可读的对象（跳过 DOMAIN）</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Export DCF…</source>
        <translation>导出 DCF…</translation>
    </message>
    <message>
        <source>Export node %1 as DCF</source>
        <translation>将节点 %1 导出为 DCF</translation>
    </message>
    <message>
        <source>Device configuration (*.dcf)</source>
        <translation>设备配置（*.dcf）</translation>
    </message>
    <message>
        <source>Apply DCF…</source>
        <translation>应用 DCF…</translation>
    </message>
    <message>
        <source>Apply a DCF to node %1</source>
        <translation>将 DCF 应用到节点 %1</translation>
    </message>
    <message>
        <source>Device configuration (*.dcf *.eds);;All files (*)</source>
        <translation>设备配置（*.dcf *.eds）;;所有文件（*）</translation>
    </message>
    <message>
        <source>Assign dictionary</source>
        <translation>指定字典</translation>
    </message>
    <message>
        <source>Read</source>
        <translation>读取</translation>
    </message>
    <message>
        <source>Write value…</source>
        <translation>写入值…</translation>
    </message>
    <message>
        <source>Copy value</source>
        <translation>复制值</translation>
    </message>
    <message>
        <source>Copy error</source>
        <translation>复制错误</translation>
    </message>
    <message>
        <source>Expand all</source>
        <translation>全部展开</translation>
    </message>
    <message>
        <source>Collapse all</source>
        <translation>全部折叠</translation>
    </message>
    <message>
        <source>Listen-only: SDO disabled</source>
        <translation>仅监听：SDO 已停用</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>Reading node %1 stopped: another node was chosen</source>
        <translation>已停止读取节点 %1：已选择另一个节点</translation>
    </message>
    <message>
        <source>Dictionary %1 of node %2 cannot be loaded</source>
        <translation>无法加载节点 %2 的字典 %1</translation>
    </message>
    <message>
        <source>Node %1 uses dictionary %2</source>
        <translation>节点 %1 使用字典 %2</translation>
    </message>
    <message>
        <source>&lt;b&gt;No node selected&lt;/b&gt; — pick one in the Nodes dock</source>
        <translation>&lt;b&gt;未选择节点&lt;/b&gt;——请在“节点”面板中选择一个</translation>
    </message>
    <message>
        <source>Select a node in the Nodes dock to see its object dictionary.</source>
        <translation>在“节点”面板中选择一个节点，即可查看其对象字典。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Node %1&lt;/b&gt;</source>
        <translation>&lt;b&gt;节点 %1&lt;/b&gt;</translation>
    </message>
    <message>
        <source> · &lt;span style=&apos;color:#b00020&apos;&gt;no dictionary&lt;/span&gt;</source>
        <translation> · &lt;span style=&apos;color:#b00020&apos;&gt;无字典&lt;/span&gt;</translation>
    </message>
    <message>
        <source> · %1 entries, %2 read</source>
        <translation> · %1 个项目，已读取 %2 个</translation>
    </message>
    <message>
        <source> · &lt;i&gt;listen-only: no SDO&lt;/i&gt;</source>
        <translation> · &lt;i&gt;仅监听：无 SDO&lt;/i&gt;</translation>
    </message>
    <message>
        <source> · &lt;i&gt;offline: no SDO&lt;/i&gt;</source>
        <translation> · &lt;i&gt;离线：无 SDO&lt;/i&gt;</translation>
    </message>
    <message>
        <source>No dictionary is known for node %1: it was not identified (1018h) or matched none in the library. Assign one to see its objects.</source>
        <translation>节点 %1 没有已知的字典：它尚未识别（1018h），或与字典库中的任何一个都不相符。请指定字典以查看其对象。</translation>
    </message>
    <message>
        <source>%1: no node selected</source>
        <translation>%1：未选择节点</translation>
    </message>
    <message>
        <source>%1: no dictionary for node %2 (assign one)</source>
        <translation>%1：节点 %2 没有字典（请指定一个）</translation>
    </message>
    <message>
        <source>%1: the bus is listen-only, nothing is sent</source>
        <translation>%1：总线为仅监听，不会发送任何内容</translation>
    </message>
    <message>
        <source>%1: not connected to a bus</source>
        <translation>%1：未连接到总线</translation>
    </message>
    <message>
        <source>Read %1</source>
        <translation>读取 %1</translation>
    </message>
    <message>
        <source>%1 %2 is write-only</source>
        <translation>%1 %2 为只写</translation>
    </message>
    <message>
        <source>Node %1 %2 %3 = %4</source>
        <translation>节点 %1 %2 %3 = %4</translation>
    </message>
    <message>
        <source>Write %1 %2 = %3 to node %4?</source>
        <translation>要将 %1 %2 = %3 写入节点 %4 吗？</translation>
    </message>
    <message>
        <source>Node %1 %2: %3</source>
        <translation>节点 %1 %2：%3</translation>
    </message>
    <message>
        <source>Write %1</source>
        <translation>写入 %1</translation>
    </message>
    <message>
        <source>%1 %2 is %3: not writable</source>
        <translation>%1 %2 为 %3：不可写入</translation>
    </message>
    <message>
        <source>Write object</source>
        <translation>写入对象</translation>
    </message>
    <message numerus="yes">
        <source>

SDO download of %n byte(s): %1</source>
        <translation>
            <numerusform>

SDO 下载 %n 字节：%1</numerusform>
        </translation>
    </message>
    <message>
        <source>Node %1 %2 written: %3</source>
        <translation>节点 %1 %2 已写入：%3</translation>
    </message>
    <message>
        <source>A read or DCF application is already running</source>
        <translation>已有读取或 DCF 应用作业在运行</translation>
    </message>
    <message>
        <source>Reading %1 objects of node %2…</source>
        <translation>正在读取节点 %2 的 %1 个对象…</translation>
    </message>
    <message>
        <source>Read of node %1 cancelled: %2 values read</source>
        <translation>已取消读取节点 %1：已读取 %2 个值</translation>
    </message>
    <message>
        <source>Node %1: %2 values read, %3 refused (red rows; the tool tip has the abort text)</source>
        <translation>节点 %1：已读取 %2 个值，%3 个被拒绝（红色行；工具提示中有中止说明）</translation>
    </message>
    <message>
        <source>Node %1: %2 values read</source>
        <translation>节点 %1：已读取 %2 个值</translation>
    </message>
    <message>
        <source>Export of node %1 failed: %2</source>
        <translation>导出节点 %1 失败：%2</translation>
    </message>
    <message>
        <source>Node %1: %2 values exported to %3</source>
        <translation>节点 %1：已将 %2 个值导出至 %3</translation>
    </message>
    <message>
        <source>Export: no node with a dictionary selected</source>
        <translation>导出：未选择有字典的节点</translation>
    </message>
    <message>
        <source>Export: wait for the running read to finish</source>
        <translation>导出：请等待当前的读取完成</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <source>Apply DCF</source>
        <translation>应用 DCF</translation>
    </message>
    <message>
        <source>Apply DCF: wait for the running read to finish</source>
        <translation>应用 DCF：请等待当前的读取完成</translation>
    </message>
    <message>
        <source>%1 is not a usable DCF: %2</source>
        <translation>%1 不是可用的 DCF：%2</translation>
    </message>
    <message>
        <source>no object could be read</source>
        <translation>没有任何对象可以读取</translation>
    </message>
    <message>
        <source>Reading node %1&apos;s current values of the %2 candidates in %3…</source>
        <translation>正在读取节点 %1 在 %3 中 %2 个候选项目的当前值…</translation>
    </message>
    <message>
        <source>Apply DCF cancelled</source>
        <translation>已取消应用 DCF</translation>
    </message>
    <message>
        <source>Node %1 already has every value of %2 (%3 entries not written)</source>
        <translation>节点 %1 已具有 %2 的所有值（%3 个项目未写入）</translation>
    </message>
    <message>
        <source>Apply DCF: the bus can no longer transmit</source>
        <translation>应用 DCF：总线已无法发送</translation>
    </message>
    <message>
        <source>Writing %1 objects to node %2…</source>
        <translation>正在将 %1 个对象写入节点 %2…</translation>
    </message>
    <message>
        <source>DCF applied to node %1: %2 written, %3 refused — first: %4</source>
        <translation>已将 DCF 应用到节点 %1：写入 %2 个，%3 个被拒绝——第一个：%4</translation>
    </message>
    <message>
        <source>DCF applied to node %1: %2 objects written%3</source>
        <translation>已将 DCF 应用到节点 %1：写入 %2 个对象%3</translation>
    </message>
    <message>
        <source> (cancelled)</source>
        <translation> （已取消）</translation>
    </message>
    <message>
        <source>Node %1: not written: %2</source>
        <translation>节点 %1：未写入：%2</translation>
    </message>
    <message>
        <source>Node %1 now answers at node-ID %2: showing node %2. Values read at node %1 were dropped; read them again.</source>
        <translation>节点 %1 现在以节点 ID %2 应答：显示节点 %2。在节点 %1 读取的值已丢弃；请重新读取。</translation>
    </message>
    <message>
        <source>Concise DCF, CiA 302-3 (*.bin)</source>
        <translation>精简 DCF，CiA 302-3 (*.bin)</translation>
    </message>
    <message>
        <source>Node %1: concise DCF with %2 entries (%3 bytes) exported to %4</source>
        <translation>节点 %1：含 %2 个条目（%3 字节）的精简 DCF 已导出至 %4</translation>
    </message>
</context>
<context>
    <name>coscope::gui::OdTreeModel</name>
    <message>
        <source>Index</source>
        <translation>索引</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>类型</translation>
    </message>
    <message>
        <source>Access</source>
        <translation>访问</translation>
    </message>
    <message>
        <source>PDO</source>
        <translation>PDO</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>默认值</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoApplyPage</name>
    <message>
        <source>Check and apply</source>
        <translation>检查并应用</translation>
    </message>
    <message>
        <source>This is exactly what will be sent, step by step (dry run: nothing has been sent yet). If the drive refuses a step, the wizard stops, tells you why and writes the old settings back.</source>
        <translation>以下正是将逐步发送的内容（模拟运行：尚未发送任何内容）。若驱动器拒绝某个步骤，向导会停止、说明原因，并写回原本的设置。</translation>
    </message>
    <message>
        <source>Keep after power-off: store the drive&apos;s parameters (1010h:01 = &quot;save&quot;)</source>
        <translation>断电后保留：保存驱动器参数（1010h:01 = &quot;save&quot;）</translation>
    </message>
    <message>
        <source>Start the drive&apos;s process data afterwards (NMT start: operational)</source>
        <translation>完成后启动驱动器的过程数据（NMT 启动：操作状态）</translation>
    </message>
    <message>
        <source>Apply to the drive</source>
        <translation>应用到驱动器</translation>
    </message>
    <message>
        <source>Without this the new mapping is lost when the drive is switched off or reset</source>
        <translation>若不勾选，驱动器断电或重置后新的映射就会丢失</translation>
    </message>
    <message>
        <source>This drive&apos;s dictionary has no 1010h (store parameters)</source>
        <translation>此驱动器的字典没有 1010h（保存参数）</translation>
    </message>
    <message>
        <source>Applying…</source>
        <translation>应用中…</translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoChoosePage</name>
    <message>
        <source>Which drive and which message</source>
        <translation>哪台驱动器、哪个报文</translation>
    </message>
    <message>
        <source>A PDO (process data object) is one CAN message that carries up to 8 bytes of live values. The drive sends its TPDOs (transmit PDOs, e.g. status and position) and receives its RPDOs (receive PDOs, e.g. commands).</source>
        <translation>PDO（过程数据对象）是一个 CAN 报文，最多携带 8 字节的实时数值。驱动器会发送它的 TPDO（发送 PDO，例如状态与位置），并接收它的 RPDO（接收 PDO，例如命令）。</translation>
    </message>
    <message>
        <source>%1 — the drive sends (transmit PDO %2)</source>
        <translation>%1——驱动器发送（发送 PDO %2）</translation>
    </message>
    <message>
        <source>%1 — the drive receives (receive PDO %2)</source>
        <translation>%1——驱动器接收（接收 PDO %2）</translation>
    </message>
    <message>
        <source>Byte</source>
        <translation>字节</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>对象</translation>
    </message>
    <message>
        <source>Bits</source>
        <translation>位</translation>
    </message>
    <message>
        <source>Drive (node):</source>
        <translation>驱动器（节点）：</translation>
    </message>
    <message>
        <source>Message (PDO):</source>
        <translation>报文（PDO）：</translation>
    </message>
    <message>
        <source>Node %1 (no dictionary)</source>
        <translation>节点 %1（无字典）</translation>
    </message>
    <message>
        <source>Node %1 — %2%3</source>
        <translation>节点 %1 — %2%3</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>Waiting for a drive to appear on the bus…</source>
        <translation>正在等待驱动器出现在总线上…</translation>
    </message>
    <message>
        <source>Reading %1 of node %2 from the drive (SDO upload of %3h and %4h)…</source>
        <translation>正在从驱动器读取节点 %2 的 %1（SDO 上传 %3h 与 %4h）…</translation>
    </message>
    <message>
        <source>Could not read %1 of node %2: %3</source>
        <translation>无法读取节点 %2 的 %1：%3</translation>
    </message>
    <message>
        <source>CAN-ID %1h%2. %3. %4 of 64 bits used.</source>
        <translation>CAN-ID %1h%2。%3。已使用 64 位中的 %4 位。</translation>
    </message>
    <message>
        <source> (switched off: COB-ID bit 31 set)</source>
        <translation> （已关闭：COB-ID 位 31 已设置）</translation>
    </message>
    <message>
        <source>Dry run (the bus is listen-only, nothing is sent): starting from the dictionary&apos;s defaults, not read from the drive: %1</source>
        <translation>模拟运行（总线为仅监听，不会发送任何内容）：以字典默认值为起点，而非从驱动器读取：%1</translation>
    </message>
    <message>
        <source>Now in the drive: %1</source>
        <translation>驱动器当前：%1</translation>
    </message>
    <message>
        <source>(nothing mapped: the message is empty)</source>
        <translation>（没有映射：报文为空）</translation>
    </message>
    <message>
        <source>Good to know about this drive:</source>
        <translation>关于此驱动器的注意事项：</translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoFrameLayout</name>
    <message>
        <source>byte %1</source>
        <translation>字节 %1</translation>
    </message>
    <message>
        <source>%1 of 64 bits — too long: a PDO carries at most 8 bytes</source>
        <translation>64 位中的 %1 位——太长：一个 PDO 最多携带 8 字节</translation>
    </message>
    <message>
        <source>%1 of 64 bits used (%2 bytes in the frame)</source>
        <translation>已使用 64 位中的 %1 位（帧中 %2 字节）</translation>
    </message>
    <message>
        <source>byte %1: %3</source>
        <extracomment>PDO layout tooltip: the bytes of the frame a mapped object fills, then its name (%3)</extracomment>
        <translation>字节 %1：%3</translation>
    </message>
    <message>
        <source>byte %1-%2: %3</source>
        <translation>字节 %1–%2：%3</translation>
    </message>
    <message>
        <source>%1 of 64 bits</source>
        <translation>已用 %1 / 64 位</translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoMappingPage</name>
    <message>
        <source>What the message carries</source>
        <translation>报文携带的内容</translation>
    </message>
    <message>
        <source>Pick the values to put in the message, in the order they appear in the frame (the PDO mapping). Double-click or drag an object to the right; drag or use Up/Down to reorder. A frame holds at most 8 bytes (64 bits).</source>
        <translation>按帧中出现的顺序挑选要放进报文的值（即 PDO 映射）。双击对象或将其拖动到右侧；以拖动或“上移／下移”调整顺序。一帧最多 8 字节（64 位）。</translation>
    </message>
    <message>
        <source>Search by name or index, e.g. velocity or 606C</source>
        <translation>按名称或索引搜索，例如 velocity 或 606C</translation>
    </message>
    <message>
        <source>Add →</source>
        <translation>添加 →</translation>
    </message>
    <message>
        <source>← Remove</source>
        <translation>← 移除</translation>
    </message>
    <message>
        <source>Up</source>
        <translation>上移</translation>
    </message>
    <message>
        <source>Down</source>
        <translation>下移</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>清除</translation>
    </message>
    <message>
        <source>As in the drive</source>
        <translation>与驱动器相同</translation>
    </message>
    <message>
        <source>Start again from the mapping read from the drive</source>
        <translation>从驱动器读到的映射重新开始</translation>
    </message>
    <message>
        <source>Objects this drive allows in the message:</source>
        <translation>此驱动器允许放入报文的对象：</translation>
    </message>
    <message>
        <source>In the message, in frame order:</source>
        <translation>报文内容（按帧顺序）：</translation>
    </message>
    <message>
        <source>The frame, byte by byte:</source>
        <translation>帧逐字节内容：</translation>
    </message>
    <message>
        <source>(no dictionary for this node: objects cannot be listed)</source>
        <translation>（此节点没有字典：无法列出对象）</translation>
    </message>
    <message>
        <source>%1  (%2, %3 bits)</source>
        <translation>%1  （%2，%3 位）</translation>
    </message>
    <message>
        <source>%1h:%2 — %3, access %4</source>
        <translation>%1h:%2 — %3，访问 %4</translation>
    </message>
    <message>
        <source>Cannot add: %1</source>
        <translation>无法添加：%1</translation>
    </message>
    <message>
        <source>%1  (%2 bits)</source>
        <translation>%1  （%2 位）</translation>
    </message>
    <message>
        <source>Too long: %1 bits. Remove objects until the total is 64 bits or less.</source>
        <translation>太长：%1 位。请移除对象直到总长度不超过 64 位。</translation>
    </message>
    <message>
        <source>Nothing mapped: the message would carry no data.</source>
        <translation>没有映射：报文将不携带任何数据。</translation>
    </message>
    <message>
        <source>Same as in the drive now.</source>
        <translation>与驱动器当前的设置相同。</translation>
    </message>
    <message>
        <source>Changed: %1 objects, %2 bits (was %3 objects, %4 bits).</source>
        <translation>已更改：%1 个对象，%2 位（原为 %3 个对象，%4 位）。</translation>
    </message>
    <message>
        <source> Many drives allow at most 8 objects per PDO.</source>
        <translation> 许多驱动器每个 PDO 最多只允许 8 个对象。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoTimingPage</name>
    <message>
        <source>When the message is sent</source>
        <translation>报文何时发送</translation>
    </message>
    <message>
        <source>Choose what makes the drive send the message (TPDO) or act on it (RPDO), and the CAN-ID it uses.</source>
        <translation>选择让驱动器发送报文（TPDO）或处理报文（RPDO）的触发条件，以及所使用的 CAN-ID。</translation>
    </message>
    <message>
        <source>On SYNC, every n-th SYNC (synchronous cyclic, type 1–240)</source>
        <translation>按 SYNC，每第 n 个 SYNC（同步周期，类型 1–240）</translation>
    </message>
    <message>
        <source>On SYNC, only after a value changed (synchronous acyclic, type 0)</source>
        <translation>按 SYNC，仅在值变化后（同步非周期，类型 0）</translation>
    </message>
    <message>
        <source>On change and/or by timer (event-driven, type 255: device profile)</source>
        <translation>值变化时和／或按计时器（事件触发，类型 255：设备子协议）</translation>
    </message>
    <message>
        <source>On change and/or by timer (event-driven, type 254: manufacturer)</source>
        <translation>值变化时和／或按计时器（事件触发，类型 254：制造商定义）</translation>
    </message>
    <message>
        <source>Other transmission type (e.g. 252/253: only on request, RTR)</source>
        <translation>其他传输类型（例如 252/253：仅在请求时，RTR）</translation>
    </message>
    <message>
        <source>every </source>
        <translation>每 </translation>
    </message>
    <message>
        <source> SYNC(s)</source>
        <translation> 个 SYNC</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>off</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>Message switched on (COB-ID bit 31 = 0: PDO valid)</source>
        <translation>报文已打开（COB-ID 位 31 = 0：PDO 有效）</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>默认值</translation>
    </message>
    <message>
        <source>The pre-defined connection set (CiA 301 §7.3.5): TPDO1 180h + node … RPDO4 500h + node</source>
        <translation>预定义连接组（CiA 301 §7.3.5）：TPDO1 180h + 节点 … RPDO4 500h + 节点</translation>
    </message>
    <message>
        <source>Sent when:</source>
        <translation>发送时机：</translation>
    </message>
    <message>
        <source>Minimum gap (inhibit time):</source>
        <translation>最小间隔（禁止时间）：</translation>
    </message>
    <message>
        <source>Timer (event timer):</source>
        <translation>计时器（事件计时器）：</translation>
    </message>
    <message>
        <source>This drive fixes the CAN-ID (COB-ID read-only): it cannot be changed, and the message cannot be switched off</source>
        <translation>此驱动器的 CAN-ID 固定（COB-ID 只读）：无法更改，报文也无法关闭</translation>
    </message>
    <message>
        <source>The drive waits at least this long between two messages (100 µs units on the bus)</source>
        <translation>驱动器在两个报文之间至少等待这么久（总线上以 100 µs 为单位）</translation>
    </message>
    <message>
        <source>Not available on this drive or for an RPDO</source>
        <translation>此驱动器或 RPDO 不提供此功能</translation>
    </message>
    <message>
        <source>Event-driven TPDO: sent at least this often; RPDO: the drive reports a timeout when no message came for this long</source>
        <translation>事件触发 TPDO：至少以此频率发送；RPDO：超过此时间未收到报文时，驱动器会报告超时</translation>
    </message>
    <message>
        <source>Not available on this drive</source>
        <translation>此驱动器不提供此功能</translation>
    </message>
    <message>
        <source>Someone must send SYNC (a SYNC producer, object 1005h/1006h) or this message never goes out.</source>
        <translation>必须有设备发送 SYNC（SYNC 生产者，对象 1005h/1006h），否则此报文永远不会发送。</translation>
    </message>
    <message>
        <source>The master must send SYNC after the message, every cycle.</source>
        <translation>主站必须在每个周期于报文之后发送 SYNC。</translation>
    </message>
    <message>
        <source>Event timer off: sent only when a mapped value changes.</source>
        <translation>事件计时器关闭：只有在映射的值变化时才发送。</translation>
    </message>
    <message>
        <source>Sent when a value changes, and at least every %1 ms.</source>
        <translation>值变化时发送，且至少每 %1 ms 发送一次。</translation>
    </message>
    <message>
        <source>Never more often than every %1 ms (inhibit time).</source>
        <translation>发送间隔不短于 %1 ms（禁止时间）。</translation>
    </message>
    <message>
        <source>CAN-ID %1h is not the default %2h: make sure no other message uses it.</source>
        <translation>CAN-ID %1h 不是默认的 %2h：请确认没有其他报文使用它。</translation>
    </message>
    <message>
        <source>The message will be switched off: the drive will neither send nor accept it.</source>
        <translation>报文将被关闭：驱动器既不发送也不接收它。</translation>
    </message>
    <message>
        <source>AIMOTOR: synchronous PDOs need SYNC from the master.</source>
        <translation>AIMOTOR：同步 PDO 需要主站发送 SYNC。</translation>
    </message>
    <message>
        <source>CAN-ID (COB-ID):</source>
        <translation>CAN-ID (COB-ID)：</translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoWizard</name>
    <message>
        <source>PDO mapping — CoScope</source>
        <translation>PDO 映射 — CoScope</translation>
    </message>
    <message>
        <source>Not connected to a bus: this wizard talks to the drive, so connect first (File ▸ Connect).</source>
        <translation>未连接到总线：此向导需要与驱动器通信，请先连接（文件 ▸ 连接）。</translation>
    </message>
    <message>
        <source>The bus is open listen-only: CoScope never transmits on it, so this wizard can neither read nor change the drive. Reconnect without listen-only to use it.</source>
        <translation>总线以仅监听方式打开：CoScope 不会在上面发送，因此此向导无法读取或更改驱动器。请取消仅监听后重新连接再使用。</translation>
    </message>
    <message>
        <source>The bus is not open (yet): wait for it to connect.</source>
        <translation>总线（尚）未打开：请等待连接完成。</translation>
    </message>
    <message>
        <source>the connection changed while reading</source>
        <translation>读取时连接已更改</translation>
    </message>
    <message>
        <source>The connection was closed while the PDO was being changed. Connect again and read the PDO to see what is in force.</source>
        <translation>更改 PDO 时连接被关闭。请重新连接并读取 PDO，确认当前生效的设置。</translation>
    </message>
    <message>
        <source>Choose a drive first.</source>
        <translation>请先选择驱动器。</translation>
    </message>
    <message>
        <source>The PDO has not been read from the drive yet.</source>
        <translation>尚未从驱动器读取 PDO。</translation>
    </message>
    <message>
        <source>PDO mapping: %1 of node %2</source>
        <translation>PDO 映射：节点 %2 的 %1</translation>
    </message>
    <message>
        <source>Keep the settings after power-off: store all parameters (1010h:01 = &quot;save&quot;, CiA 301 §7.5.2.13)</source>
        <translation>断电后保留设置：保存所有参数（1010h:01 = &quot;save&quot;，CiA 301 §7.5.2.13）</translation>
    </message>
    <message>
        <source>Start process data: the drive goes operational and sends/uses its PDOs (NMT start)</source>
        <translation>启动过程数据：驱动器进入操作状态并发送／使用其 PDO（NMT 启动）</translation>
    </message>
    <message>
        <source>A change is already being applied.</source>
        <translation>已有更改正在应用。</translation>
    </message>
    <message>
        <source>Stopped at step %1 of %2: %3%4.</source>
        <translation>停止于第 %1 步（共 %2 步）：%3%4。</translation>
    </message>
    <message>
        <source>What the drive answered: %1</source>
        <translation>驱动器的响应：%1</translation>
    </message>
    <message>
        <source>What to check: %1</source>
        <translation>检查事项：%1</translation>
    </message>
    <message>
        <source>The previous settings were written back: %1 works as before (%2 objects, %3 bits). The drive was left pre-operational.</source>
        <translation>已写回先前的设置：%1 与之前相同（%2 个对象，%3 位）。驱动器维持在预操作状态。</translation>
    </message>
    <message>
        <source>Writing the previous settings back failed as well (%1): read the PDO again and check it before starting the drive.</source>
        <translation>写回先前的设置也失败了（%1）：启动驱动器前，请重新读取 PDO 并检查。</translation>
    </message>
    <message>
        <source>Nothing was changed on the drive.</source>
        <translation>驱动器上没有任何更改。</translation>
    </message>
    <message>
        <source>Done: %1 of node %2 now carries %3 objects (%4 bits), checked by reading back. The trace and the plot decode it with the new layout from now on.</source>
        <translation>完成：节点 %2 的 %1 现在携带 %3 个对象（%4 位），已读回确认。跟踪与图表从现在起以新的配置解码。</translation>
    </message>
    <message>
        <source> The drive is pre-operational: start it (NMT start) to make PDOs flow.</source>
        <translation> 驱动器处于预操作状态：启动它（NMT 启动）即可开始发送 PDO。</translation>
    </message>
    <message>
        <source> Starting the drive failed: %1</source>
        <translation> 启动驱动器失败：%1</translation>
    </message>
    <message>
        <source> The drive was started (operational).</source>
        <translation> 驱动器已启动（操作状态）。</translation>
    </message>
    <message>
        <source>
But storing failed (%1): the new mapping works now and is lost at power-off. %2</source>
        <translation>
但保存失败（%1）：新的映射当前有效，断电后会丢失。%2</translation>
    </message>
    <message>
        <source> Stored in the drive (kept after power-off).</source>
        <translation> 已保存到驱动器（断电后保留）。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::PlotDock</name>
    <message>
        <source>Plot</source>
        <translation>图表</translation>
    </message>
    <message>
        <source>Rolling window</source>
        <translation>滚动窗口</translation>
    </message>
    <message>
        <source>Whole trace</source>
        <translation>整个跟踪</translation>
    </message>
    <message>
        <source>Follow the newest samples over a window of seconds, or show the whole trace</source>
        <translation>在数秒宽的窗口内跟随最新的采样，或显示整个跟踪</translation>
    </message>
    <message>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <source>Width of the rolling window</source>
        <translation>滚动窗口的宽度</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Freeze the view (data keeps being recorded); zoom and pan pause too</source>
        <translation>冻结画面（数据仍持续记录）；缩放与平移也会暂停</translation>
    </message>
    <message>
        <source>Stacked</source>
        <translation>堆叠</translation>
    </message>
    <message>
        <source>Shared plot</source>
        <translation>共享图表</translation>
    </message>
    <message>
        <source>Stacked plots sharing the time axis, or one plot with a y-axis per signal</source>
        <translation>共享时间轴的堆叠图表，或每个信号各有一条 Y 轴的单一图表</translation>
    </message>
    <message>
        <source>Autoscale</source>
        <translation>自动缩放</translation>
    </message>
    <message>
        <source>Fit the y-axes to the visible data</source>
        <translation>将 Y 轴调整为符合可见数据</translation>
    </message>
    <message>
        <source>Auto Y</source>
        <translation>自动 Y</translation>
    </message>
    <message>
        <source>Keep the y-axes fitted; off: drag and wheel zoom the y-axes too</source>
        <translation>持续自动调整 Y 轴；关闭时：拖动与滚轮也会缩放 Y 轴</translation>
    </message>
    <message>
        <source>Legend</source>
        <translation>图例</translation>
    </message>
    <message>
        <source>Clear cursors</source>
        <translation>清除光标</translation>
    </message>
    <message>
        <source>Add raw signal…</source>
        <translation>添加原始信号…</translation>
    </message>
    <message>
        <source>Plot bits of any frame (start bit, length, type, byte order, factor, offset, unit): for devices without a dictionary</source>
        <translation>绘制任何帧的位（起始位、长度、类型、字节顺序、系数、偏移、单位）：适用于没有字典的设备</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <source>PNG image…</source>
        <translation>PNG 图片…</translation>
    </message>
    <message>
        <source>PDF document…</source>
        <translation>PDF 文档…</translation>
    </message>
    <message>
        <source>CSV of the visible window…</source>
        <translation>可见窗口的 CSV…</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <source>No frames from the bus yet.</source>
        <translation>尚未从总线收到帧。</translation>
    </message>
    <message>
        <source>Reading the log…</source>
        <translation>正在读取日志文件…</translation>
    </message>
    <message>
        <source>The log holds no frames.</source>
        <translation>日志文件中没有帧。</translation>
    </message>
    <message>
        <source>Nothing to plot: connect to a bus (Bus menu) or open a log (File ▸ Open log…).</source>
        <translation>没有可绘制的内容：请连接到总线（总线菜单）或打开日志文件（文件 ▸ 打开日志文件…）。</translation>
    </message>
    <message>
        <source>bus %1 node %2</source>
        <translation>总线 %1 节点 %2</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>No PDOs in this trace (%L1 frames): the plot shows the objects that PDOs carry.</source>
        <translation>此跟踪中没有 PDO（%L1 帧）：图表显示的是 PDO 所携带的对象。</translation>
    </message>
    <message>
        <source>Nodes seen: %1.</source>
        <translation>已看到的节点：%1。</translation>
    </message>
    <message>
        <source>Nodes send their PDOs once started (Nodes dock: right-click ▸ Start).</source>
        <translation>节点启动后才会发送 PDO（节点面板：右键单击 ▸ 启动）。</translation>
    </message>
    <message>
        <source>No dictionary for these nodes, so their PDOs cannot be decoded: %1. Assign one in the Nodes dock (right-click the node ▸ Assign dictionary…)%2; its PDO signals are then listed here.</source>
        <translation>这些节点没有字典，因此无法解码其 PDO：%1。请在节点面板中指定字典（在节点上右键单击 ▸ 指定字典…）%2；之后其 PDO 信号就会列在这里。</translation>
    </message>
    <message>
        <source> or identify the nodes with Bus ▸ Scan network</source>
        <translation> 或以“总线 ▸ 扫描网络”识别节点</translation>
    </message>
    <message>
        <source>PDOs whose mapping is not known (changed before the trace began): %1.</source>
        <translation>映射未知的 PDO（在跟踪开始前已更改）：%1。</translation>
    </message>
    <message>
        <source>Raw signal %1 added: it is listed under COB-ID %2h once its frames are read</source>
        <translation>已添加原始信号 %1：读到其帧后，会列在 COB-ID %2h 之下</translation>
    </message>
    <message>
        <source>%1: cannot write the PNG image</source>
        <translation>%1：无法写入 PNG 图片</translation>
    </message>
    <message>
        <source>%1: cannot write the PDF document</source>
        <translation>%1：无法写入 PDF 文档</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>PNG 图片（*.png）</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>PDF 文档（*.pdf）</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV（*.csv）</translation>
    </message>
    <message>
        <source>Export plot</source>
        <translation>导出图表</translation>
    </message>
    <message>
        <source>Plot exported to %1</source>
        <translation>图表已导出至 %1</translation>
    </message>
</context>
<context>
    <name>coscope::gui::PlotView</name>
    <message>
        <source>Pick signals on the left</source>
        <translation>请在左侧选择信号</translation>
    </message>
    <message>
        <source>Time [s]</source>
        <translation>时间 [s]</translation>
    </message>
    <message>
        <source>Click the plot to place cursor A (jumps to the frame), Shift+click for cursor B.</source>
        <translation>单击图表可放置光标 A（并跳至该帧），Shift+单击放置光标 B。</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ProcessDataDock</name>
    <message>
        <source>Switch on</source>
        <translation>接通主回路</translation>
    </message>
    <message>
        <source>Enable voltage</source>
        <translation>使能电压</translation>
    </message>
    <message>
        <source>Quick stop (0 = active)</source>
        <translation>快速停止（0 = 生效）</translation>
    </message>
    <message>
        <source>Enable operation</source>
        <translation>使能运行</translation>
    </message>
    <message>
        <source>New set-point</source>
        <translation>新设定点</translation>
    </message>
    <message>
        <source>Change set immediately</source>
        <translation>立即更新设定</translation>
    </message>
    <message>
        <source>Relative</source>
        <translation>相对</translation>
    </message>
    <message>
        <source>Fault reset</source>
        <translation>故障复位</translation>
    </message>
    <message>
        <source>Halt</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Process data</source>
        <translation>过程数据</translation>
    </message>
    <message>
        <source>Node:</source>
        <translation>节点：</translation>
    </message>
    <message>
        <source>Send once</source>
        <translation>发送一次</translation>
    </message>
    <message>
        <source>On change</source>
        <translation>变化时发送</translation>
    </message>
    <message>
        <source>Every N ms</source>
        <translation>每 N ms</translation>
    </message>
    <message>
        <source>With each SYNC</source>
        <translation>随每个 SYNC</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>启动</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>发送</translation>
    </message>
    <message>
        <source>Arm motion…</source>
        <translation>准备运行…</translation>
    </message>
    <message>
        <source>Hold to run</source>
        <translation>按住运行</translation>
    </message>
    <message>
        <source>RPDOs with motion objects are sent only while this button is held down; releasing it sends halt and velocity 0.</source>
        <translation>含运动对象的 RPDO 仅在按住此按钮时发送；松开时发送暂停与速度 0。</translation>
    </message>
    <message>
        <source>Hold to run was not fed: the drive was sent halt and velocity 0.</source>
        <translation>“按住运行”未持续按住：已向驱动器发送暂停与速度 0。</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>Node %1: its dictionary %2 could not be loaded: %3</source>
        <translation>节点 %1：无法加载其对象字典 %2：%3</translation>
    </message>
    <message>
        <source>Could not read: %1</source>
        <translation>无法读取：%1</translation>
    </message>
    <message>
        <source>RPDO%1 (%2h)</source>
        <translation>RPDO%1（%2h）</translation>
    </message>
    <message>
        <source>%1 (bit %2)</source>
        <translation>%1（bit %2）</translation>
    </message>
    <message>
        <source>Decimal, 0x1F or 1Fh</source>
        <translation>十进制、0x1F 或 1Fh</translation>
    </message>
    <message>
        <source>In %1</source>
        <translation>单位 %1</translation>
    </message>
    <message>
        <source>TPDOs: no values seen yet (are they sent on SYNC?)</source>
        <translation>TPDO：尚未收到数值（是否在 SYNC 时才发送？）</translation>
    </message>
    <message>
        <source>TPDOs: %1</source>
        <translation>TPDO：%1</translation>
    </message>
    <message>
        <source>No bus is connected.</source>
        <translation>未连接总线。</translation>
    </message>
    <message>
        <source>The bus is listen-only or not open: nothing can be sent.</source>
        <translation>总线为仅监听或未打开：无法发送。</translation>
    </message>
    <message>
        <source>The bus&apos;s master services are not available.</source>
        <translation>该总线的主站服务不可用。</translation>
    </message>
    <message>
        <source>No node with a dictionary is known yet: scan the network or assign a dictionary.</source>
        <translation>尚无已知且有对象字典的节点：请扫描网络或指定对象字典。</translation>
    </message>
    <message>
        <source>This node&apos;s dictionary maps no RPDO.</source>
        <translation>该节点的对象字典未映射任何 RPDO。</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Sent with each SYNC: start the SYNC producer (Bus menu) for frames to go out.</source>
        <translation>随每个 SYNC 发送：请启动 SYNC 生产者（总线菜单）才会发出帧。</translation>
    </message>
    <message>
        <source>Sent.</source>
        <translation>已发送。</translation>
    </message>
    <message>
        <source>Arm motion</source>
        <translation>准备运行</translation>
    </message>
    <message>
        <source>The RPDOs of node %1 carry motion objects (controlword, mode, targets). While &quot;Hold to run&quot; is held, they are sent with the values shown and the motor can move. Releasing the button sends halt and velocity 0.

Make sure the axis is free to move. Arm?</source>
        <translation>节点 %1 的 RPDO 含运动对象（控制字、模式、目标值）。按住“按住运行”时会以显示的数值发送，电机可能转动。松开按钮时发送暂停与速度 0。

请确认轴可以自由移动。要准备运行吗？</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ProgramDownloadDialog</name>
    <message>
        <source>Download program to node %1</source>
        <translation>下载程序到节点 %1</translation>
    </message>
    <message>
        <source>Program image file</source>
        <translation>程序映像文件</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <source>Program file:</source>
        <translation>程序文件：</translation>
    </message>
    <message>
        <source>The program number: sub-index of 1F50h program data and 1F51h program control (CiA 302-3)</source>
        <translation>程序编号：1F50h 程序数据与 1F51h 程序控制的子索引（CiA 302-3）</translation>
    </message>
    <message>
        <source>Program number:</source>
        <translation>程序编号：</translation>
    </message>
    <message>
        <source>Block transfer (segmented when the node declines it)</source>
        <translation>块传输（节点不支持时改用分段传输）</translation>
    </message>
    <message>
        <source>Start the program after the download (the node resets)</source>
        <translation>下载后启动程序（节点会复位）</translation>
    </message>
    <message>
        <source>What the node reports now</source>
        <translation>节点当前报告的内容</translation>
    </message>
    <message>
        <source>Software version (100Ah):</source>
        <translation>软件版本（100Ah）：</translation>
    </message>
    <message>
        <source>Software identification (1F56h):</source>
        <translation>软件识别码（1F56h）：</translation>
    </message>
    <message>
        <source>Flash status (1F57h):</source>
        <translation>闪存状态（1F57h）：</translation>
    </message>
    <message>
        <source>Read again</source>
        <translation>重新读取</translation>
    </message>
    <message>
        <source>Download</source>
        <translation>下载</translation>
    </message>
    <message>
        <source>Cancel download</source>
        <translation>取消下载</translation>
    </message>
    <message>
        <source>Program image for node %1</source>
        <translation>节点 %1 的程序映像文件</translation>
    </message>
    <message>
        <source>Program images (*.img *.bin *.hex);;All files (*)</source>
        <translation>程序映像文件 (*.img *.bin *.hex);;所有文件 (*)</translation>
    </message>
    <message>
        <source>The bus was closed: nothing is claimed about the node&apos;s program.</source>
        <translation>总线已关闭：不对节点的程序做任何保证。</translation>
    </message>
    <message>
        <source>Listen-only bus: a program download would transmit</source>
        <translation>仅监听总线：程序下载需要发送报文</translation>
    </message>
    <message>
        <source>Connect to a bus first</source>
        <translation>请先连接到总线</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>未读取</translation>
    </message>
    <message>
        <source>Download again (from the start)</source>
        <translation>重新下载（从头开始）</translation>
    </message>
    <message>
        <source>Node %1 stops its application for the download (1F51h = 0): a motor it drives is not controlled until the new program has started.</source>
        <translation>节点 %1 下载期间会停止其应用程序（1F51h = 0）：在新程序启动前，它所驱动的电机不受控制。</translation>
    </message>
    <message>
        <source>CoScope enabled %1: it is disabled first (6040h = 0).</source>
        <translation>CoScope 已使能 %1：会先将其断开电压（6040h = 0）。</translation>
    </message>
    <message>
        <source>reading…</source>
        <translation>读取中…</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>无应答</translation>
    </message>
    <message>
        <source>Reading the program state (1F56h, 1F57h, 100Ah)</source>
        <translation>读取程序状态（1F56h、1F57h、100Ah）</translation>
    </message>
    <message>
        <source>Disabling the drive (6040h = 0)</source>
        <translation>断开驱动器电压（6040h = 0）</translation>
    </message>
    <message>
        <source>Stopping the program (1F51h:%1 = 0)</source>
        <translation>停止程序（1F51h:%1 = 0）</translation>
    </message>
    <message>
        <source>Clearing the program (1F51h:%1 = 3)</source>
        <translation>清除程序（1F51h:%1 = 3）</translation>
    </message>
    <message>
        <source>Downloading the program data (1F50h:%1)</source>
        <translation>下载程序数据（1F50h:%1）</translation>
    </message>
    <message>
        <source>Starting the program (1F51h:%1 = 1)</source>
        <translation>启动程序（1F51h:%1 = 1）</translation>
    </message>
    <message>
        <source>Waiting for the node&apos;s boot-up</source>
        <translation>等待节点的启动报文</translation>
    </message>
    <message>
        <source>Reading the new program state</source>
        <translation>读取新程序状态</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>完成</translation>
    </message>
    <message>
        <source>larger than 16 MiB</source>
        <translation>大于 16 MiB</translation>
    </message>
    <message>
        <source>Cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>%1 is empty.</source>
        <translation>%1 为空。</translation>
    </message>
    <message>
        <source>Download %1 (%2 bytes) into program %3 of node %4?</source>
        <translation>要将 %1（%2 字节）下载到节点 %4 的程序 %3 吗？</translation>
    </message>
    <message>
        <source>The node stops its application (1F51h = 0) and its program is replaced. If the download fails, the node may have no valid program until a download succeeds.</source>
        <translation>节点会停止其应用程序（1F51h = 0），其程序将被替换。若下载失败，在下载成功之前节点可能没有有效的程序。</translation>
    </message>
    <message>
        <source>CoScope disables %1 first (6040h = 0).</source>
        <translation>CoScope 会先断开 %1 的电压（6040h = 0）。</translation>
    </message>
    <message>
        <source>Then the node starts the new program and resets (boot-up).</source>
        <translation>接着节点会启动新程序并复位（启动报文）。</translation>
    </message>
    <message>
        <source>%L1 of %L2 bytes, %L3 KiB/s</source>
        <translation>%L1 / %L2 字节，%L3 KiB/s</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>Done: node %1 runs the new program. Software version %2 → %3, software identification %4 → %5.</source>
        <translation>完成：节点 %1 正在运行新程序。软件版本 %2 → %3，软件识别码 %4 → %5。</translation>
    </message>
    <message>
        <source>Downloaded; the program was not started (node %1 stays stopped).</source>
        <translation>已下载；程序未启动（节点 %1 保持停止）。</translation>
    </message>
    <message>
        <source>%L1 bytes in %L2 s.</source>
        <translation>%L1 字节，耗时 %L2 秒。</translation>
    </message>
    <message>
        <source>The node&apos;s program was not touched.</source>
        <translation>节点的程序未被改动。</translation>
    </message>
    <message>
        <source>Nothing is claimed: the node may hold no valid program. Download again to start over from the beginning.</source>
        <translation>不做任何保证：节点可能没有有效的程序。请重新下载，从头开始。</translation>
    </message>
    <message>
        <source>Cancelled at “%1”: %2</source>
        <translation>已在“%1”取消：%2</translation>
    </message>
    <message>
        <source>Failed at “%1”: %2</source>
        <translation>在“%1”失败：%2</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ProjectActions</name>
    <message>
        <source>CoScope projects (*.coscope *.coscope.json);;All files (*)</source>
        <translation>CoScope 项目 (*.coscope *.coscope.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>&amp;New project</source>
        <translation>新建项目(&amp;N)</translation>
    </message>
    <message>
        <source>Open &amp;project…</source>
        <translation>打开项目(&amp;P)…</translation>
    </message>
    <message>
        <source>Open project</source>
        <translation>打开项目</translation>
    </message>
    <message>
        <source>Save pro&amp;ject</source>
        <translation>保存项目(&amp;J)</translation>
    </message>
    <message>
        <source>Save project &amp;as…</source>
        <translation>项目另存为(&amp;A)…</translation>
    </message>
    <message>
        <source>Recent pro&amp;jects</source>
        <translation>最近的项目(&amp;J)</translation>
    </message>
    <message>
        <source>&amp;Project</source>
        <translation>项目(&amp;P)</translation>
    </message>
    <message>
        <source>&amp;Compare with the machine…</source>
        <translation>与机器比较(&amp;C)…</translation>
    </message>
    <message>
        <source>&amp;Back up the machine</source>
        <translation>备份机器(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Apply the project…</source>
        <translation>应用项目(&amp;A)…</translation>
    </message>
    <message>
        <source>Unsaved project</source>
        <translation>项目未保存</translation>
    </message>
    <message>
        <source>The project &quot;%1&quot; has changes that are not saved. Save the project first?</source>
        <translation>项目“%1”有尚未保存的更改。要先保存项目吗？</translation>
    </message>
    <message>
        <source>New project: Project ▸ Back up the machine reads the drives into it</source>
        <translation>新项目：项目 ▸ 备份机器 会把驱动器读入项目</translation>
    </message>
    <message>
        <source>Project %1 opened</source>
        <translation>已打开项目 %1</translation>
    </message>
    <message>
        <source>Connect to the project&apos;s bus %1?</source>
        <translation>要连接到项目的总线 %1 吗？</translation>
    </message>
    <message>
        <source>Save project</source>
        <translation>保存项目</translation>
    </message>
    <message>
        <source>Project saved to %1</source>
        <translation>项目已保存到 %1</translation>
    </message>
    <message>
        <source>Back up the machine</source>
        <translation>备份机器</translation>
    </message>
    <message>
        <source>Connect to the machine&apos;s bus first (not listen-only): the backup reads the drives.</source>
        <translation>请先连接到机器的总线（非仅监听）：备份会读取驱动器。</translation>
    </message>
    <message>
        <source>Backing up the machine: reading every drive…</source>
        <translation>正在备份机器：读取每台驱动器…</translation>
    </message>
    <message>
        <source>Backing up the machine: %1</source>
        <translation>正在备份机器：%1</translation>
    </message>
    <message>
        <source>Node %1: %2</source>
        <translation>节点 %1：%2</translation>
    </message>
    <message>
        <source>Node %1: NOT backed up: %2</source>
        <translation>节点 %1：未备份：%2</translation>
    </message>
    <message numerus="yes">
        <source>Backup done: %n node(s)</source>
        <translation>
            <numerusform>备份完成：%n 个节点</numerusform>
        </translation>
    </message>
    <message>
        <source>The drives&apos; configuration is in the project; save the project to keep it.</source>
        <translation>驱动器的配置已在项目中；请保存项目以保留。</translation>
    </message>
    <message>
        <source>Download the project&apos;s program…</source>
        <translation>下载项目的程序…</translation>
    </message>
    <message>
        <source>Load the program (firmware) the project names for the selected node: CiA 302-3 program download</source>
        <translation>为选中的节点载入项目指定的程序（固件）：CiA 302-3 程序下载</translation>
    </message>
    <message>
        <source>The bus closed before the backup was finished: the project is as it was.</source>
        <translation>备份完成前总线已关闭：项目保持原样。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ProjectSession</name>
    <message>
        <source>Untitled project</source>
        <translation>未命名项目</translation>
    </message>
</context>
<context>
    <name>coscope::gui::RawSignalDialog</name>
    <message>
        <source>Add raw signal</source>
        <translation>添加原始信号</translation>
    </message>
    <message>
        <source>0x181</source>
        <translation>0x181</translation>
    </message>
    <message>
        <source>The frame&apos;s identifier: decimal or 0x hex; over 7FFh a 29-bit identifier</source>
        <translation>帧的标识符：十进制或 0x 十六进制；大于 7FFh 为 29 位标识符</translation>
    </message>
    <message>
        <source>Intel: the least significant bit; Motorola: the most significant bit (DBC numbering, bit 7 of byte 0 = 7)</source>
        <translation>Intel：最低有效位；Motorola：最高有效位（DBC 编号方式，字节 0 的位 7 = 7）</translation>
    </message>
    <message>
        <source> bits</source>
        <translation> 位</translation>
    </message>
    <message>
        <source>Unsigned</source>
        <translation>无符号</translation>
    </message>
    <message>
        <source>Signed</source>
        <translation>有符号</translation>
    </message>
    <message>
        <source>Float (IEEE 754, 32 or 64 bits)</source>
        <translation>浮点数（IEEE 754，32 或 64 位）</translation>
    </message>
    <message>
        <source>Intel (little-endian, as CANopen PDOs)</source>
        <translation>Intel（小端序，与 CANopen PDO 相同）</translation>
    </message>
    <message>
        <source>Motorola (big-endian)</source>
        <translation>Motorola（大端序）</translation>
    </message>
    <message>
        <source>value = raw × factor + offset</source>
        <translation>值 = 原始值 × 系数 + 偏移</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>COB-ID</source>
        <translation>COB-ID</translation>
    </message>
    <message>
        <source>Start bit</source>
        <translation>起始位</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>长度</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>类型</translation>
    </message>
    <message>
        <source>Byte order</source>
        <translation>字节顺序</translation>
    </message>
    <message>
        <source>Factor</source>
        <translation>系数</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>偏移</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <source>Plot bits of any frame, for a device without a dictionary.</source>
        <translation>绘制任何帧的位，适用于没有字典的设备。</translation>
    </message>
    <message>
        <source>Give the signal a name.</source>
        <translation>请为信号命名。</translation>
    </message>
    <message>
        <source>The COB-ID must be a number up to 1FFFFFFFh (0x181, 385 or 181h).</source>
        <translation>COB-ID 必须是不超过 1FFFFFFFh 的数字（0x181、385 或 181h）。</translation>
    </message>
    <message>
        <source>The factor must be a number other than 0.</source>
        <translation>系数必须是不为 0 的数字。</translation>
    </message>
    <message>
        <source>The offset must be a number.</source>
        <translation>偏移必须是数字。</translation>
    </message>
    <message>
        <source>A float is 32 or 64 bits long.</source>
        <translation>浮点数长度为 32 或 64 位。</translation>
    </message>
    <message>
        <source>The signal ends past byte 64 of the frame.</source>
        <translation>信号结束位置超出帧的第 64 字节。</translation>
    </message>
    <message>
        <source>This signal cannot be read: %1.</source>
        <translation>无法读取此信号：%1。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::RecentFilesMenu</name>
    <message>
        <source>%1 (not found)</source>
        <translation>%1（找不到）</translation>
    </message>
    <message>
        <source>%1 no longer exists</source>
        <translation>%1 已不存在</translation>
    </message>
    <message>
        <source>Clear recent</source>
        <translation>清除最近记录</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ScriptPreview</name>
    <message>
        <source>What it does</source>
        <translation>用途</translation>
    </message>
    <message>
        <source>Script line</source>
        <translation>脚本行</translation>
    </message>
    <message>
        <source>Why</source>
        <translation>原因</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <source>Save as script…</source>
        <translation>另存为脚本…</translation>
    </message>
    <message>
        <source>Write these steps to a text file that `coscope-cli script run BUS FILE` replays</source>
        <translation>将这些步骤写入文本文件，可用 `coscope-cli script run BUS FILE` 回放</translation>
    </message>
    <message numerus="yes">
        <source>%n step(s) will be sent</source>
        <translation>
            <numerusform>将发送 %n 个步骤</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 — %n step(s)</source>
        <translation>
            <numerusform>%1 — %n 个步骤</numerusform>
        </translation>
    </message>
    <message>
        <source>done</source>
        <translation>完成</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>失败</translation>
    </message>
    <message>
        <source>running…</source>
        <translation>运行中…</translation>
    </message>
    <message>
        <source>Save as script</source>
        <translation>另存为脚本</translation>
    </message>
    <message>
        <source>Command scripts (*.txt);;All files (*)</source>
        <translation>指令脚本（*.txt）;;所有文件（*）</translation>
    </message>
    <message>
        <source>Could not save the script: %1</source>
        <translation>无法保存脚本：%1</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ScriptRunPanel</name>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Stopped: the connection changed.</source>
        <translation>已停止：连接已更改。</translation>
    </message>
    <message>
        <source>Send these commands?</source>
        <translation>要发送这些指令吗？</translation>
    </message>
    <message>
        <source>A run is in progress.</source>
        <translation>正在运行中。</translation>
    </message>
    <message>
        <source>The bus cannot send now.</source>
        <translation>总线当前无法发送。</translation>
    </message>
    <message>
        <source>Step %1 of %2…</source>
        <translation>第 %1 步（共 %2 步）…</translation>
    </message>
    <message numerus="yes">
        <source>Done: %n step(s) completed.</source>
        <translation>
            <numerusform>完成：已完成 %n 个步骤。</numerusform>
        </translation>
    </message>
    <message>
        <source>Stopped at step %1; nothing further was sent.</source>
        <translation>停止于第 %1 步；之后没有再发送任何内容。</translation>
    </message>
    <message>
        <source>Failed at %1</source>
        <translation>失败于 %1</translation>
    </message>
</context>
<context>
    <name>coscope::gui::SignalPicker</name>
    <message>
        <source>Search signals (name, object, node)</source>
        <translation>搜索信号（名称、对象、节点）</translation>
    </message>
    <message>
        <source>Signal</source>
        <translation>信号</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>对象</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <source>Factor</source>
        <translation>系数</translation>
    </message>
    <message>
        <source>No signal matches “%1”.</source>
        <translation>没有符合“%1”的信号。</translation>
    </message>
    <message>
        <source>Bus %1, COB-ID %2h (raw signals)</source>
        <translation>总线 %1，COB-ID %2h（原始信号）</translation>
    </message>
    <message>
        <source>COB-ID %1h (raw signals)</source>
        <translation>COB-ID %1h（原始信号）</translation>
    </message>
    <message>
        <source>Bus %1, node %2</source>
        <translation>总线 %1，节点 %2</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>value = raw × factor + %1 (defined: × %2 %3)</source>
        <translation>值 = 原始值 × 系数 + %1（定义：× %2 %3）</translation>
    </message>
    <message>
        <source>value = raw × factor (dictionary: %1 %2)</source>
        <translation>值 = 原始值 × 系数（字典：%1 %2）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::TraceDock</name>
    <message>
        <source>Trace</source>
        <translation>跟踪</translation>
    </message>
    <message>
        <source>Close this report</source>
        <translation>关闭此报告</translation>
    </message>
    <message>
        <source>Follow</source>
        <translation>跟随</translation>
    </message>
    <message>
        <source>Follow new frames (scrolling up pauses)</source>
        <translation>跟随新帧（向上滚动时暂停）</translation>
    </message>
    <message>
        <source>Absolute time</source>
        <translation>绝对时间</translation>
    </message>
    <message>
        <source>Relative time</source>
        <translation>相对时间</translation>
    </message>
    <message>
        <source>Delta time</source>
        <translation>时间差</translation>
    </message>
    <message>
        <source>Latest per ID</source>
        <translation>每个 ID 最新帧</translation>
    </message>
    <message>
        <source>One row per COB-ID showing its latest frame</source>
        <translation>每个 COB-ID 一行，显示其最新帧</translation>
    </message>
    <message>
        <source>Group SDO</source>
        <translation>SDO 分组</translation>
    </message>
    <message>
        <source>Group SDO transfers: each transfer as one row; click its ▸ to show its frames</source>
        <translation>将 SDO 传输分组：每次传输显示为一行；单击 ▸ 显示其帧</translation>
    </message>
    <message>
        <source>Filter: node:5 svc:sdo,emcy id:580-5FF text</source>
        <translation>筛选：node:5 svc:sdo,emcy id:580-5FF 文本</translation>
    </message>
    <message>
        <source>Find</source>
        <translation>查找</translation>
    </message>
    <message>
        <source>Previous</source>
        <translation>上一个</translation>
    </message>
    <message>
        <source>Find previous</source>
        <translation>查找上一个</translation>
    </message>
    <message>
        <source>Next</source>
        <translation>下一个</translation>
    </message>
    <message>
        <source>Find next</source>
        <translation>查找下一个</translation>
    </message>
    <message>
        <source>Bookmark</source>
        <translation>书签</translation>
    </message>
    <message>
        <source>Toggle a bookmark on the selected frame (Ctrl+B); F2 / Shift+F2 jump</source>
        <translation>在选中的帧上切换书签（Ctrl+B）；F2 / Shift+F2 跳转</translation>
    </message>
    <message>
        <source>%L1 rows, %L2 frames</source>
        <translation>%L1 行，%L2 帧</translation>
    </message>
    <message>
        <source>%L1 SDO transfers grouped</source>
        <translation>已将 %L1 个 SDO 传输分组</translation>
    </message>
    <message>
        <source>%L1 of %L2 frames</source>
        <translation>%L1／%L2 帧</translation>
    </message>
    <message>
        <source>%L1 frames</source>
        <translation>%L1 帧</translation>
    </message>
    <message>
        <source>&apos;%1&apos; not found: the trace is empty</source>
        <translation>找不到“%1”：跟踪为空</translation>
    </message>
    <message>
        <source>&apos;%1&apos; not found</source>
        <translation>找不到“%1”</translation>
    </message>
    <message>
        <source>Select a frame to bookmark</source>
        <translation>请选择要加书签的帧</translation>
    </message>
    <message>
        <source>No bookmarks (Ctrl+B sets one)</source>
        <translation>没有书签（按 Ctrl+B 设置）</translation>
    </message>
    <message>
        <source>Next bookmark</source>
        <translation>下一个书签</translation>
    </message>
    <message>
        <source>Previous bookmark</source>
        <translation>上一个书签</translation>
    </message>
    <message>
        <source>The project&apos;s trace filter is not valid: %1</source>
        <translation>项目的跟踪过滤条件无效：%1</translation>
    </message>
    <message>
        <source>How times are shown, here and in the Events, Health and Plot docks: the wall clock (from the log&apos;s header or the capture), seconds since the first frame, or since the row before (this table only)</source>
        <translation>时间的显示方式（此处以及事件、健康状态和图表面板）：实际时钟时间（取自日志文件的文件头或捕获时）、自第一帧起的秒数，或与上一行的时间差（仅此表格）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::TraceModel</name>
    <message>
        <source>loading…</source>
        <extracomment>Trace row whose frame is being read back from the capture journal on disk</extracomment>
        <translation>正在加载…</translation>
    </message>
    <message>
        <source>Click to expand or collapse the transfer&apos;s frames</source>
        <translation>单击可展开或折叠此传输的帧</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>时间（秒）</translation>
    </message>
    <message>
        <source>Δt (s)</source>
        <extracomment>Trace column: time since the previous frame, in seconds</extracomment>
        <translation>Δt（秒）</translation>
    </message>
    <message>
        <source>No.</source>
        <extracomment>Trace columns: frame number, time, bus, COB-ID, node, CANopen service, direction (Rx/Tx), data length, data bytes, decoded summary</extracomment>
        <translation>编号</translation>
    </message>
    <message>
        <source>Bus</source>
        <translation>总线</translation>
    </message>
    <message>
        <source>COB-ID</source>
        <translation>COB-ID</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>节点</translation>
    </message>
    <message>
        <source>Service</source>
        <translation>服务</translation>
    </message>
    <message>
        <source>Dir</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>Len</source>
        <translation>长度</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>数据</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>摘要</translation>
    </message>
    <message>
        <source>Bus lost at %1, back at %2 (%3 s without frames)</source>
        <translation>总线于 %1 中断，%2 恢复（%3 秒没有帧）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::TransmitDock</name>
    <message>
        <source>Transmit</source>
        <translation>发送</translation>
    </message>
    <message>
        <source>Frame in candump syntax, e.g. 601#4018100100000000, 123#R, 123##1AABB (CAN FD)</source>
        <translation>candump 语法的帧，例如 601#4018100100000000、123#R、123##1AABB（CAN FD）</translation>
    </message>
    <message>
        <source>every</source>
        <translation>每</translation>
    </message>
    <message>
        <source>once</source>
        <translation>一次</translation>
    </message>
    <message>
        <source>Period in ms, to the microsecond (0.5 = 500 µs); empty or 0 = sent once only</source>
        <translation>周期（ms），精确到微秒（0.5 = 500 µs）；空白或 0 = 只发送一次</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>添加</translation>
    </message>
    <message>
        <source>Add the frame to the list without sending it</source>
        <translation>将帧添加到列表，但不发送</translation>
    </message>
    <message>
        <source>Add and send</source>
        <translation>添加并发送</translation>
    </message>
    <message>
        <source>Add the frame to the list and send it (Enter)</source>
        <translation>将帧添加到列表并发送（Enter）</translation>
    </message>
    <message>
        <source>Send selected</source>
        <translation>发送所选项</translation>
    </message>
    <message>
        <source>Send the selected rows once (Enter in the list)</source>
        <translation>将所选的行各发送一次（在列表中按 Enter）</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>移除</translation>
    </message>
    <message>
        <source>Remove the selected rows (Delete)</source>
        <translation>移除所选的行（Delete）</translation>
    </message>
    <message>
        <source>Stop all</source>
        <translation>全部停止</translation>
    </message>
    <message>
        <source>Stop every periodic row</source>
        <translation>停止所有周期发送的行</translation>
    </message>
    <message>
        <source>Every periodic frame stopped</source>
        <translation>所有周期帧已停止</translation>
    </message>
    <message>
        <source>Connect to a bus first: the frames below are kept and sent once a bus is open.</source>
        <translation>请先连接到总线：下列帧会保留，总线打开后即可发送。</translation>
    </message>
    <message>
        <source>Listen-only connection: CoScope sends nothing, so the transmit list is disabled.</source>
        <translation>仅监听连接：CoScope 不发送任何帧，因此发送列表已停用。</translation>
    </message>
    <message>
        <source>The bus is not open: nothing can be sent now.</source>
        <translation>总线未打开：目前无法发送。</translation>
    </message>
    <message numerus="yes">
        <source>%n periodic frame(s) running</source>
        <translation>
            <numerusform>%n 个周期帧正在发送</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot read “%1”: %2</source>
        <translation>无法解读“%1”：%2</translation>
    </message>
    <message>
        <source>“%1” is not a period in ms (0 = once only, at least 0.1 ms)</source>
        <translation>“%1”不是以 ms 为单位的周期（0 = 只发送一次，至少 0.1 ms）</translation>
    </message>
    <message>
        <source>Not sent: %1</source>
        <translation>未发送：%1</translation>
    </message>
    <message>
        <source>Give the row a period (Every, ms) to send it periodically</source>
        <translation>请为此行设置周期（每，ms）才能周期发送</translation>
    </message>
    <message>
        <source>Cannot send periodically: %1</source>
        <translation>无法周期发送：%1</translation>
    </message>
    <message>
        <source>It is RPDO%1 of node %2, which carries %3: it can make the motor move.</source>
        <translation>这是节点 %2 的 RPDO%1，其中带有 %3：可能使电机运转。</translation>
    </message>
    <message>
        <source>It is RPDO%1 of node %2, a drive whose mapping CoScope does not know: it can make the motor move.</source>
        <translation>这是节点 %2 的 RPDO%1，此驱动器的映射 CoScope 不知道：可能使电机运转。</translation>
    </message>
    <message>
        <source>Send a motion command?</source>
        <translation>要发送运动命令吗？</translation>
    </message>
    <message>
        <source>%1

Send %2%3?</source>
        <translation>%1

要发送 %2%3 吗？</translation>
    </message>
    <message>
        <source> every %1 ms</source>
        <translation>（每 %1 ms）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::TransmitModel</name>
    <message>
        <source>Send every %1 ms while checked</source>
        <translation>勾选时每 %1 ms 发送一次</translation>
    </message>
    <message>
        <source>(remote)</source>
        <translation>（远程）</translation>
    </message>
    <message>
        <source>once</source>
        <translation>一次</translation>
    </message>
    <message>
        <source>Periodic sending on or off</source>
        <translation>开启或关闭周期发送</translation>
    </message>
    <message>
        <source>CAN identifier in hex (601, 601h or 0x601)</source>
        <translation>十六进制的 CAN 标识符（601、601h 或 0x601）</translation>
    </message>
    <message>
        <source>Data bytes in hex (40 18 10 01)</source>
        <translation>十六进制的数据字节（40 18 10 01）</translation>
    </message>
    <message>
        <source>Period in ms, to the microsecond (0.5 = 500 µs); 0 = sent once only</source>
        <translation>周期（ms），精确到微秒（0.5 = 500 µs）；0 = 只发送一次</translation>
    </message>
    <message>
        <source>Periodic</source>
        <translation>周期</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>29-bit</source>
        <translation>29 位</translation>
    </message>
    <message>
        <source>RTR</source>
        <translation>RTR</translation>
    </message>
    <message>
        <source>FD</source>
        <translation>FD</translation>
    </message>
    <message>
        <source>BRS</source>
        <translation>BRS</translation>
    </message>
    <message>
        <source>DLC</source>
        <translation>DLC</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>数据</translation>
    </message>
    <message>
        <source>Every (ms)</source>
        <translation>每（ms）</translation>
    </message>
    <message>
        <source>Sent</source>
        <translation>已发送</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>备注</translation>
    </message>
    <message>
        <source>ID %1h needs 29 bits</source>
        <translation>ID %1h 需要 29 位</translation>
    </message>
    <message>
        <source>CAN FD has no remote frames</source>
        <translation>CAN FD 没有远程帧</translation>
    </message>
    <message>
        <source>“%1” is not a CAN identifier (hex, up to 1FFFFFFFh)</source>
        <translation>“%1”不是 CAN 标识符（十六进制，最大 1FFFFFFFh）</translation>
    </message>
    <message>
        <source>DLC must be a valid length of 0-%1 bytes</source>
        <translation>DLC 必须是 0-%1 字节的有效长度</translation>
    </message>
    <message>
        <source>“%1” is not up to %2 hex bytes</source>
        <translation>“%1”不是最多 %2 个十六进制字节</translation>
    </message>
    <message>
        <source>“%1” is not a period in ms (0 = once only, at least 0.1 ms)</source>
        <translation>“%1”不是以 ms 为单位的周期（0 = 只发送一次，至少 0.1 ms）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::WizardFramesPane</name>
    <message>
        <source>Frames on the bus for this wizard</source>
        <translation>此向导在总线上的帧</translation>
    </message>
</context>
<context>
    <name>coscope::gui::WizardGuard</name>
    <message>
        <source>No bus is connected, so nothing can be sent. Connect to the bus first; you can still prepare the steps and save them as a script.</source>
        <translation>未连接到任何总线，因此无法发送。请先连接到总线；您仍可先准备步骤并另存为脚本。</translation>
    </message>
    <message>
        <source>The bus is open in listen-only mode: CoScope never transmits on it. Reconnect without listen-only to send these commands; you can still prepare the steps and save them as a script.</source>
        <translation>总线以仅监听模式打开：CoScope 不会在上面发送。请取消仅监听后重新连接才能发送这些指令；您仍可先准备步骤并另存为脚本。</translation>
    </message>
    <message>
        <source>The bus is still opening; sending is possible once it is open.</source>
        <translation>总线仍在打开中；打开后即可发送。</translation>
    </message>
    <message>
        <source>The bus is not open (%1), so nothing can be sent.</source>
        <translation>总线未打开（%1），因此无法发送。</translation>
    </message>
    <message>
        <source>The bus was lost (%1); CoScope is reconnecting. Sending is possible again once it is back.</source>
        <translation>总线已中断（%1）；CoScope 正在重新连接。恢复后即可再发送。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Workspace</name>
    <message>
        <source>cannot create the folder %1</source>
        <translation>无法创建文件夹 %1</translation>
    </message>
    <message>
        <source>The capture is not journaled to disk (%1); it is kept in memory only</source>
        <translation>捕获内容未写入磁盘日志（%1）；仅保存在内存中</translation>
    </message>
    <message>
        <source>Capture stopped: cannot write the capture journal %1 (%2). The trace keeps the %L3 frames received.</source>
        <translation>捕获已停止：无法写入捕获日志 %1（%2）。跟踪中保留已收到的 %L3 帧。</translation>
    </message>
    <message>
        <source>Bus lost: %1. Retrying with back-off; node states are unknown until their next heartbeat.</source>
        <translation>总线中断：%1。正以逐步延长的间隔重试；各节点的状态在下一次心跳之前未知。</translation>
    </message>
    <message>
        <source>Bus back after %1 s: frames between are missing from the trace</source>
        <translation>总线在 %1 秒后恢复：中断期间的帧不在跟踪中</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s) dropped (receive queue full), %1 in total</source>
        <translation>
            <numerusform>丢失 %n 帧（接收队列已满），累计 %1 帧</numerusform>
        </translation>
    </message>
    <message>
        <source>node %1 axis %2</source>
        <translation>节点 %1 轴 %2</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>Disable voltage (6040h = 0000h) sent to %1 before the bus closed, and seen on the bus</source>
        <translation>总线关闭前已向%1发送断开电压（Disable voltage，6040h = 0000h），并在总线上看到该帧</translation>
    </message>
    <message>
        <source>%1 may still be enabled: its Disable voltage (6040h = 0000h) was not seen on the bus before it closed (%2). Check the drive.</source>
        <translation>%1 可能仍处于使能状态：总线关闭前未在总线上看到其断开电压（Disable voltage，6040h = 0000h）帧（%2）。请检查驱动器。</translation>
    </message>
    <message>
        <source>Node guarding lost: no answer within the node life time of %1 ms (guard time %2 ms × %3)</source>
        <translation>节点保护丢失：在节点寿命时间 %1 ms 内无应答（节点守护时间 %2 ms × %3）</translation>
    </message>
    <message>
        <source>Heartbeat lost: none within the consumer time of %1 ms</source>
        <translation>心跳丢失：在消费者时间 %1 ms 内未收到</translation>
    </message>
    <message>
        <source>Node guarding answers again</source>
        <translation>节点保护恢复应答</translation>
    </message>
    <message>
        <source>Heartbeat back</source>
        <translation>心跳恢复</translation>
    </message>
    <message>
        <source>%1: no CAN frame found (read as %2)</source>
        <translation>%1：找不到任何 CAN 帧（以 %2 格式读取）</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation>第 %1 行：%2</translation>
    </message>
    <message>
        <source>%1: cannot read the file</source>
        <translation>%1：无法读取文件</translation>
    </message>
    <message>
        <source>%1: not a format CoScope reads (tried candump, Vector ASC and BLF, PEAK TRC, pcap/pcapng, CoScope CSV, SavvyCAN GVRET, BUSMASTER, IXXAT, Kvaser and ASAM MDF4); read as %2 by its name, no CAN frame was found</source>
        <translation>%1：不是 CoScope 可读取的格式（已尝试 candump、Vector ASC 和 BLF、PEAK TRC、pcap/pcapng、CoScope CSV、SavvyCAN GVRET、BUSMASTER、IXXAT、Kvaser 和 ASAM MDF4）；按文件名作为 %2 读取，未找到 CAN 报文</translation>
    </message>
</context>
<context>
    <name>coscope::gui::help::HelpWindow</name>
    <message>
        <source>CoScope guide</source>
        <translation>CoScope 使用指南</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>后退</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>前进</translation>
    </message>
    <message>
        <source>Contents</source>
        <translation>目录</translation>
    </message>
</context>
<context>
    <name>coscope::gui::help::ShortcutsDialog</name>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>键盘快捷键</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>按键</translation>
    </message>
    <message>
        <source>Action</source>
        <translation>操作</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>位置</translation>
    </message>
</context>
</TS>
